"""The world's tests: a package, so that pytest puts its parent, emu/world
(the modules under test), first on the path, as it does for any package."""
