/* Links the conversions of whatever compiler runtime it is given: with Debian's
 * m68k libgcc (built for the 68020/68881) the ISA scan must find FPU
 * instructions in it, which shows the scan can fail (assure/cpu32_isa.py). */
float int_to_float(int x);
float int_to_float(int x) { return (float)x; }
float unsigned_to_float(unsigned x);
float unsigned_to_float(unsigned x) { return (float)x; }
void _start(void);
void _start(void) {}
