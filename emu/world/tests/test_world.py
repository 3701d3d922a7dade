"""The world model alone: geometry, kinematics, collisions, sensors, energy."""
import json
import math
import os

import pytest

from world import ArenaError, World, load_arena
from record import Recorder


def test_arena_file_errors(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text("{not json")
    with pytest.raises(ArenaError, match="not valid JSON"):
        load_arena(str(bad))
    with pytest.raises(ArenaError, match="No such file"):
        load_arena(str(tmp_path / "missing.json"))
    with open(os.path.join(os.path.dirname(__file__), "..", "arenas", "default.json")) as f:
        a = json.load(f)
    a["robot"]["start"] = [5, 5, 0]
    bad.write_text(json.dumps(a))
    with pytest.raises(ArenaError, match="start is not inside"):
        load_arena(str(bad))
    a["robot"].pop("start")
    bad.write_text(json.dumps(a))
    with pytest.raises(ArenaError, match="robot: 'start' is a required property"):
        load_arena(str(bad))


def test_straight_line_and_turn_in_place(arena):
    w = World(arena, 1)
    x0, y0, th0 = w.x, w.y, w.th
    cpm = w.counts_per_m
    w.step(0.01, cpm * 0.1, cpm * 0.1, 0.5, 0.5)          # 10 cm straight ahead
    assert math.hypot(w.x - x0, w.y - y0) == pytest.approx(0.1)
    assert w.th == pytest.approx(th0)
    arc = math.pi / 2 * w.axle / 2                       # quarter turn on the spot
    w.step(0.01, -cpm * arc, cpm * arc, 0.5, 0.5)
    assert math.remainder(w.th - th0, 2 * math.pi) == pytest.approx(math.pi / 2)
    assert w.distance == pytest.approx(0.1)


def test_wall_stops_the_robot_and_counts_one_collision(arena):
    w = World(arena, 1)
    w.th = 0.0                                           # facing the east wall at x = 4
    for _ in range(400):
        w.step(0.01, 50, 50, 0.5, 0.5)
    assert w.x == pytest.approx(arena["size"][0] - w.r)
    assert w.collisions["wall"] == 1
    assert w.bumpers == (True, True)
    assert w.sensors()["bumper_left"] == 0


def test_ir_rises_as_the_wall_nears(arena):
    w = World(arena, 1)
    w.th = 0.0
    w.y = 1.2                                            # clear of the competitors
    readings = []
    for x in (2.8, 3.2, 3.5, 3.7):
        w.x = x
        readings.append(w._ir(0.0))
    assert readings == sorted(readings)
    assert readings[0] == pytest.approx(12.0, abs=1.0)    # 1.08 m: out of range
    assert readings[-1] > 90                             # 0.18 m


def test_light_is_stronger_on_the_side_of_the_station(arena):
    w = World(arena, 1)
    sx, sy, _ = w.station
    w.x, w.y = sx + 1.0, sy
    w.th = math.pi / 2                                   # station to the left
    assert w._light(math.radians(40), [(sx, sy, 1.0)]) > w._light(-math.radians(40), [(sx, sy, 1.0)])


def test_battery_drains_and_charges_in_the_station(arena):
    w = World(arena, 1)
    soc = w.soc
    w.step(1.0, 0, 0, 1.0, 1.0)
    b = arena["robot"]["battery"]
    assert soc - w.soc == pytest.approx((b["idle_w"] + 2 * b["motor_w"]) / b["capacity_j"])
    w.x, w.y, _ = w.station
    before = w.soc
    w.step(1.0, 0, 0, 0.0, 0.0)
    assert w.charging and w.soc > before
    # Both competitors on: the station gives power minus their draw.
    st = arena["station"]
    draw = sum(c["draw_w"] for c in arena["competitors"])
    assert w.soc - before == pytest.approx((st["power_w"] - draw - b["idle_w"]) / b["capacity_j"])


def test_empty_battery_ends_the_robot(arena):
    w = World(arena, 1)
    w.soc = 0.001
    w.step(1.0, 0, 0, 1.0, 1.0)
    assert not w.alive and w.death_time == pytest.approx(1.0)


def test_knocking_a_competitor_turns_it_off_for_a_while(arena):
    w = World(arena, 1)
    c = arena["competitors"][0]
    w.x, w.y, w.th = c["x"] - 0.3, c["y"], 0.0
    full = w.station_available_w()
    for _ in range(100):
        w.step(0.01, 40, 40, 0.5, 0.5)
    assert w.competitor_hits == 1
    assert w.station_available_w() == pytest.approx(full + c["draw_w"])
    w.step(c["off_s"], 0, 0, 0, 0)
    assert w.station_available_w() == pytest.approx(full)


def test_noise_is_seeded(arena):
    a, b, c = World(arena, 5), World(arena, 5), World(arena, 6)
    sa = [a.sensors() for _ in range(20)]
    assert sa == [b.sensors() for _ in range(20)]
    assert sa != [c.sensors() for _ in range(20)]


def test_recorder_hash_follows_the_trajectory(arena):
    w1, w2 = World(arena, 1), World(arena, 1)
    r1, r2 = Recorder(w1), Recorder(w2)
    for r, w, d in ((r1, w1, 10), (r2, w2, 11)):
        w.step(0.01, d, d, 0.1, 0.1)
        r.step(10_000_000)
    assert r1.digest() != r2.digest()


def test_motor_model_matches_the_board_response():
    """The wheels' model (motors.py) follows the board's first-order response:
    speed 2000 (1 - e^(-t/tau)) counts/s at full duty, tau 50 ms."""
    from motors import MotorModel
    m = MotorModel()
    turned = sum(m.advance(1.0, 0.0078125) for _ in range(128))       # 1 s
    exact = 2000.0 * (1.0 - 0.05 * (1.0 - math.exp(-1.0 / 0.05)))    # integral of the speed
    assert m.speed == pytest.approx(2000.0 * (1 - math.exp(-20.0)))
    assert abs(turned - exact) <= 1
    assert m.advance(-1.0, 1.0) < 0


def test_robot_wiring_names_match_the_arena():
    """pdl/robot.h names the ports the arena's robot is wired to: every arena
    file's wiring must be the one those names say."""
    import re
    root = os.path.join(os.path.dirname(__file__), "..", "..", "..")
    text = open(os.path.join(root, "pdl", "robot.h")).read()
    names = dict((n, (p, int(i))) for n, p, i in
                 re.findall(r"#define (ROBOT_\w+) +(PDL_\w+), (\d+)", text))
    key = {"LIGHT_LEFT": "ain_light_left", "LIGHT_RIGHT": "ain_light_right",
           "IR_LEFT": "ain_ir_left", "IR_RIGHT": "ain_ir_right", "BATTERY": "ain_battery",
           "COMP_LEFT": "ain_comp_left", "COMP_RIGHT": "ain_comp_right",
           "BUMPER_LEFT": "ip_bumper_left", "BUMPER_RIGHT": "ip_bumper_right",
           "CHARGING": "ip_charging", "MOTOR_LEFT": "motor_left", "MOTOR_RIGHT": "motor_right"}
    port = {"ain": "PDL_ANALOG_IN", "ip": "PDL_BINARY_IN", "motor": "PDL_MOTOR"}
    assert sorted(names) == sorted("ROBOT_" + k for k in key)
    arenas = os.path.join(root, "emu", "world", "arenas")
    for f in sorted(os.listdir(arenas)):
        wiring = json.load(open(os.path.join(arenas, f)))["wiring"]
        for short, field in key.items():
            assert names["ROBOT_" + short] == (port[field.split("_")[0]], wiring[field]), (f, short)
