"""The losses from the motor shaft to the grid (ballscrew.axis.drive), against closed forms."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from ballscrew.axis.drive import (
    DriveSpec,
    MotorConstants,
    copper_loss,
    dc_link_flows,
    drive_energy,
    phase_resistance,
)
from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import parse_case
from ballscrew.io.machine import parse_machine
from ballscrew.materials import STANDARD_GRAVITY

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"

CASE = """
title = "t"
[screw]
designation = "HIWIN R32-05K4-FSC"
[lubricant]
name = "PAO ISO VG 68"
[motor]
rated_speed = "3000 rpm"
"""


def _motor(extra: str) -> MotorConstants:
    return MotorConstants.from_case(parse_case(CASE + extra).motor)


def test_a_held_torque_over_a_dwell_costs_3_r_i_squared_t() -> None:
    # 5 N*m held 7 s by 2.5 N*m/A and 0.8 ohm a phase: I = 2 A, 3 * 0.8 * 4 * 7 = 67.2 J.
    # Two samples at the ends and a constant torque: the trapezoid is exact (rounding only).
    motor = MotorConstants(2.5, phase_resistance=0.8)
    e = drive_energy([0.0, 7.0], [5.0, 5.0], [0.0, 0.0], motor, DriveSpec(1.0, dc_link="resistor"))
    assert e.copper_loss == pytest.approx(67.2, rel=1e-14)
    assert e.shaft_supplied == 0.0 and e.grid == pytest.approx(67.2, rel=1e-14)


def test_terminal_resistance_is_twice_the_phase_resistance() -> None:
    assert float(phase_resistance(3.0, "terminal")) == 1.5
    phase = _motor('torque_constant = "2 N*m/A"\nwinding_resistance = "1.1 ohm"\n'
                   'resistance_kind = "phase"')  # fmt: skip
    terminal = _motor('torque_constant = "2 N*m/A"\nwinding_resistance = "2.2 ohm"\n'
                      'resistance_kind = "terminal"')  # fmt: skip
    assert phase.phase_resistance == pytest.approx(terminal.phase_resistance, rel=1e-15)
    # Star, line current I: two phases between two terminals, so 1.5 R_tt I^2 = 3 R_ph I^2.
    assert float(copper_loss(2.0, float(phase_resistance(2.2, "terminal")))) == pytest.approx(
        1.5 * 2.2 * 4.0, rel=1e-15
    )


def test_a_resistance_without_its_kind_is_refused() -> None:
    with pytest.raises(BallScrewInputError, match=r"motor\.resistance_kind"):
        parse_case(CASE + 'winding_resistance = "1 ohm"')
    with pytest.raises(BallScrewInputError, match=r"motor\.iron_loss"):
        parse_case(CASE + 'iron_loss = "3 mm"')
    with pytest.raises(BallScrewInputError, match="a torque constant") as typed:
        parse_case(CASE + 'torque_constant = "1.8 Nm"')  # the amperes forgotten
    assert typed.value.field == "motor.torque_constant"
    with pytest.raises(BallScrewInputError, match="rated_speed"):
        parse_case(CASE.replace('rated_speed = "3000 rpm"', 'iron_loss = "40 W"'))


def test_an_iron_loss_given_as_a_power_is_its_drag_at_the_rated_speed() -> None:
    # 40 W at 3000 rpm = 314.16 rad/s: 0.12732 N*m, the same as given as that torque.
    power = _motor('iron_loss = "40 W"')
    torque = _motor('iron_loss = "0.127324 N*m"')
    assert power.iron_loss_torque == pytest.approx(40.0 / (3000 * math.pi / 30), rel=1e-12)
    assert power.iron_loss_torque == pytest.approx(torque.iron_loss_torque, rel=1e-5)


def test_a_missing_torque_constant_is_left_out_not_assumed() -> None:
    motor = _motor('winding_resistance = "1 ohm"\nresistance_kind = "phase"')
    e = drive_energy([0, 1, 2], [1.0, 2.0, 0.5], [0, 100, 50], motor,
                     DriveSpec(efficiency=0.97, dc_link="regenerative"), name="axes.Y")  # fmt: skip
    assert e.copper_loss is None and e.drive_loss is None and e.grid is None
    assert any("copper loss: not computed, axes.Y has no motor.torque_constant" in n
               for n in e.left_out)  # fmt: skip
    assert e.as_dict()["grid_energy_J"] is None


def _accelerate_and_stop(n: int = 100_001) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Pure inertia J = 0.01 kg m^2 at alpha = 100 rad/s^2 for 2 s, then braked as hard.

    The torque's step at 2 s is two samples at the same time (as the planner writes a
    block's end and the next one's start).
    """
    up = np.linspace(0.0, 2.0, n)
    t = np.concatenate([up, up + 2.0])
    alpha = np.concatenate([np.full(n, 100.0), np.full(n, -100.0)])
    w = np.concatenate([100.0 * up, 200.0 - 100.0 * up])
    return t, 0.01 * alpha, w


def test_a_resistor_burns_what_the_braking_gives_back() -> None:
    # T = +-1 N*m, K_t = 1 N*m/A, R_ph = 0.5 ohm: I = 1 A, P_cu = 1.5 W throughout.
    # Braking, P_dc = -omega + 1.5 regenerates while omega > 1.5 rad/s, from 200 rad/s:
    # burnt = int_{1.5}^{200} (w - 1.5) dw / 100 = (200 - 1.5)^2 / 200 = 197.01 J.
    t, torque, w = _accelerate_and_stop()
    e = drive_energy(t, torque, w, MotorConstants(1.0, phase_resistance=0.5),
                     DriveSpec(efficiency=1.0, dc_link="resistor"))  # fmt: skip
    burnt = (200.0 - 1.5) ** 2 / 200.0
    assert e.copper_loss == pytest.approx(1.5 * 4.0, rel=1e-12)
    # The shaft's 0.5 J omega^2 = 200 J comes back whole (net 0); the trapezoid's error is at
    # the one step where P_dc changes sign: (dt = 2e-5 s)^2 * 100 W/s, far below 1e-9 J.
    assert e.shaft_supplied == pytest.approx(200.0, rel=1e-9)
    assert e.dc_link is not None
    assert e.dc_link.burnt == pytest.approx(burnt, rel=1e-9)
    # grid = shaft (net 0) + losses + burnt, the resistor returning nothing.
    assert e.grid == pytest.approx(0.0 + e.copper_loss + burnt, rel=1e-9)
    assert e.dc_link.returned == 0.0


@pytest.mark.parametrize("link", ["regenerative", "resistor", "storage"])
def test_the_grid_balances_the_shaft_and_the_losses(link: str) -> None:
    # A wandering torque and speed (seeded), every loss on: the DC link's flows computed from
    # P_dc must equal the parts integrated one by one, for every choice of DC link.
    rng = np.random.default_rng(7)
    t = np.cumsum(rng.uniform(1e-3, 5e-3, 4000))
    torque = np.cumsum(rng.normal(0.0, 0.2, t.size))
    w = 50.0 * np.sin(t * 3.0) + rng.normal(0.0, 5.0, t.size)
    motor = MotorConstants(1.7, 1.5, 314.0, 1.3, 0.1)
    spec = DriveSpec(standby=5.0, per_ampere=4.0, resistance=0.2, dc_link=link,
                     storage=30.0 if link == "storage" else None)  # fmt: skip
    e = drive_energy(t, torque, w, motor, spec)
    assert e.dc_link is not None and e.copper_loss and e.iron_loss and e.drive_loss
    f = e.dc_link
    net_shaft = e.shaft_supplied - e.shaft_returned
    parts = net_shaft + e.copper_loss + e.iron_loss + e.drive_loss
    # drawn - returned = shaft + losses + burnt + stored; sums of a few thousand steps.
    assert f.drawn - f.returned == pytest.approx(parts + f.burnt + f.stored, rel=1e-10)
    assert f.regenerated > 0.0
    if link == "regenerative":
        assert f.burnt == f.stored == 0.0 and f.returned == f.regenerated
    if link == "resistor":
        assert f.burnt == f.regenerated and f.returned == 0.0


def test_a_storage_gives_back_what_it_took_until_it_is_full() -> None:
    # Regenerate 500 J, then draw 800 J: a 300 J storage keeps 300 J (200 J burnt) and gives
    # it to the motoring, which draws 500 J from the grid; a large one burns nothing.
    t, p = [0.0, 1.0, 1.0, 2.0], [-500.0, -500.0, 800.0, 800.0]
    small = dc_link_flows(t, p, "storage", 300.0)
    assert (small.drawn, small.burnt, small.stored) == (500.0, 200.0, 0.0)
    large = dc_link_flows(t, p, "storage", 1e6)
    assert (large.drawn, large.burnt, large.stored) == (300.0, 0.0, 0.0)
    none = dc_link_flows(t, p, "storage", 0.0)
    resistor = dc_link_flows(t, p, "resistor")
    assert (none.drawn, none.burnt) == (resistor.drawn, resistor.burnt) == (800.0, 500.0)


def test_the_machine_files_drive_keys_are_checked() -> None:
    text = (EXAMPLES / "machine_vmc.toml").read_text("utf-8")
    machine = parse_machine(text, folder=EXAMPLES)
    assert machine.drive["dc_link"] == "resistor" and machine.drive["per_ampere"] == 6.0
    with pytest.raises(BallScrewInputError, match=r"machine\.dc_link"):
        parse_machine(text.replace('value = "resistor"', 'value = "flywheel"'), folder=EXAMPLES)
    with pytest.raises(BallScrewInputError, match=r"machine\.dc_link_storage"):
        parse_machine(text.replace('value = "resistor"', 'value = "storage"'), folder=EXAMPLES)
    with pytest.raises(BallScrewInputError, match=r"machine\.drive_efficiency"):
        parse_machine(text.replace('model = "complete"', 'model = "complete"\n'
                                   'drive_efficiency = "97 %"'), folder=EXAMPLES)  # fmt: skip


VERTICAL = """
title = "Z alone"
[machine]
rapid_feed = "10 m/min"
drive_efficiency = "100 %"
dc_link = "resistor"
[axes.Z]
case = "vertical_32x5.toml"
max_feed = "10 m/min"
max_acceleration = "2 m/s^2"
max_jerk = "40 m/s^3"
travel = ["-300 mm", "0 mm"]
"""


def test_a_vertical_axis_standing_in_a_dwell_draws_its_holding_energy() -> None:
    pytest.importorskip("ruckig")
    from ballscrew.program import run_program

    machine = parse_machine(VERTICAL, folder=EXAMPLES)
    case = machine.axes["Z"].case
    motor = MotorConstants.from_case(case.motor)
    assert motor.torque_constant is not None and motor.phase_resistance is not None
    # Holding the 120 kg slide on a 5 mm lead: T = m g l / 2 pi (direct drive).
    hold = case.axis["moving_mass"] * STANDARD_GRAVITY * case.screw.lead / (2.0 * math.pi)
    runs = {}
    for dwell in (1.0, 4.0):
        program = f"G1 Z-50 F3000\nG4 P{dwell}\nG0 Z-100\nM30\n"
        runs[dwell] = run_program(machine, program).axes["Z"].drive
    longer, shorter = runs[4.0], runs[1.0]
    assert longer is not None and shorter is not None
    assert longer.copper_loss is not None and shorter.copper_loss is not None
    # 3 s more of standing: 3 R_ph (T/K_t)^2 * 3 s exactly (the same motion otherwise, the
    # torque at rest constant); 1e-9 for the sums over the samples.
    expected = 3.0 * motor.phase_resistance * (hold / motor.torque_constant) ** 2 * 3.0
    assert expected > 1.0
    assert longer.copper_loss - shorter.copper_loss == pytest.approx(expected, rel=1e-9)
    # With an ideal drive, the grid pays exactly that copper loss for the longer stand.
    assert longer.grid is not None and shorter.grid is not None
    assert longer.grid - shorter.grid == pytest.approx(expected, rel=1e-9)


def test_a_motor_tables_electrical_columns_reach_the_candidates_case() -> None:
    from ballscrew.io.motors import parse_motors
    from ballscrew.select.pool import case_text

    header = ("name, rated_torque [N*m], peak_torque [N*m], max_speed [1/min], "
              "rotor_inertia [kg*cm^2], torque_constant [N*m/A], winding_resistance [ohm], "
              "resistance_kind, iron_loss [W]")  # fmt: skip
    (motor,) = parse_motors(f"{header}\nM1, 7.7, 23, 3000, 18, 1.8, 2.4, terminal, 45\n")
    assert (motor.torque_constant, motor.winding_resistance, motor.resistance_kind,
            motor.iron_loss) == (1.8, 2.4, "terminal", "45 W")  # fmt: skip
    with pytest.raises(BallScrewInputError, match="resistance_kind"):
        parse_motors(f"{header.replace(', resistance_kind', '')}\nM1, 7.7, 23, 3000, 18, 1.8, "
                     "2.4, 45\n")  # fmt: skip
    with pytest.raises(BallScrewInputError, match="phase or terminal"):
        parse_motors(f"{header}\nM1, 7.7, 23, 3000, 18, 1.8, 2.4, star, 45\n")
    from ballscrew.io.designation import catalog_screws

    text = (EXAMPLES / "xy_table_32x10.toml").read_text("utf-8")
    screw = next(r for r in catalog_screws() if r.nut == "double")
    case = parse_case(case_text(text, screw, "double", 0.06, None, motor=motor))
    constants = MotorConstants.from_case(case.motor)
    assert constants.torque_constant == 1.8 and constants.phase_resistance == 1.2
    # The candidate's rated speed is written to 8 digits (314.15927 rad/s): 1e-7.
    assert constants.iron_loss_torque == pytest.approx(45.0 / (3000 * math.pi / 30), rel=1e-7)


def test_energy_books_the_holding_current_of_a_vertical_axis_in_its_dwells() -> None:
    # `ballscrew energy`'s move dwells at both ends of its stroke: 1 s more of dwell each is
    # 2 s more of holding the 120 kg slide, 3 R_ph (m g l / 2 pi K_t)^2 * 2 s.
    from ballscrew.axis.duty import profile_from_move, run_energy
    from ballscrew.io.case import load_case

    case = load_case(EXAMPLES / "vertical_32x5.toml")
    motor = MotorConstants.from_case(case.motor)
    assert motor.torque_constant is not None and motor.phase_resistance is not None
    copper = {}
    for dwell in (0.5, 1.5):
        move = {"stroke": 0.3, "feed": 0.2, "acceleration": 3.0, "dwell": dwell}
        run = run_energy(case, profile_from_move(move, 1), ["complete"], move=move)
        copper[dwell] = run.as_dict()["copper_loss_J"]
    hold = case.axis["moving_mass"] * STANDARD_GRAVITY * case.screw.lead / (2.0 * math.pi)
    expected = 3.0 * motor.phase_resistance * (hold / motor.torque_constant) ** 2 * 2.0
    assert copper[1.5] - copper[0.5] == pytest.approx(expected, rel=1e-9)


def test_program_json_gives_each_axis_its_losses_and_says_what_is_left_out(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    pytest.importorskip("ruckig")
    import json

    from cli_runner import run

    nc = tmp_path / "part.nc"
    nc.write_text("G0 X100 Y100 Z-10\nG1 X200 F2000\nG4 P1\nG1 Y200\nM30\n", encoding="utf-8")
    code, out, err = run(["program", str(nc), "--machine", str(EXAMPLES / "machine_vmc.toml"),
                          "--json", str(tmp_path / "r.json")], capsys)  # fmt: skip
    assert code == 0, err
    assert "copper loss [J]" in out and "energy from the grid (axis alone) [J]" in out
    doc = json.loads((tmp_path / "r.json").read_text("utf-8"))
    for a in doc["axes"].values():
        assert a["copper_loss_J"] > 0 and a["drive_loss_J"] > 0 and a["grid_energy_J"] > 0
        assert a["left_out"] == []
    # The example's drive burns what it regenerates: grid = shaft + losses + burnt, summed.
    t = doc["machine_totals"]
    shaft = t["supplied_energy_J"] - t["regenerated_energy_J"]
    losses = t["copper_loss_J"] + t["motor_iron_loss_J"] + t["drive_loss_J"]
    assert t["grid_energy_J"] == pytest.approx(shaft + losses + t["burnt_J"], rel=1e-9)
    # A machine file without the drive, on a case without K_t: None, and said.
    text = (EXAMPLES / "machine_vmc.toml").read_text("utf-8")
    text = "\n".join(ln for ln in text.splitlines()
                     if not ln.startswith(("drive_", "dc_link", "torque_constant")))  # fmt: skip
    (tmp_path / "vertical_32x5.toml").write_text(
        "\n".join(ln for ln in (EXAMPLES / "vertical_32x5.toml").read_text("utf-8").splitlines()
                  if not ln.startswith("torque_constant")), encoding="utf-8")  # fmt: skip
    (tmp_path / "m.toml").write_text(text, encoding="utf-8")
    code, out, err = run(["program", str(nc), "--machine", str(tmp_path / "m.toml"),
                          "--json", str(tmp_path / "r2.json")], capsys)  # fmt: skip
    assert code == 0, err
    assert "left out: copper loss: not computed, axes.Z has no motor.torque_constant" in err
    doc = json.loads((tmp_path / "r2.json").read_text("utf-8"))
    assert doc["axes"]["X"]["copper_loss_J"] is None and doc["axes"]["X"]["grid_energy_J"] is None
    assert any("machine.dc_link" in n for n in doc["axes"]["X"]["left_out"])


@pytest.mark.parametrize("shared", [False, True])
def test_a_shared_dc_link_passes_one_axis_braking_to_another_motoring(shared: bool) -> None:
    # Axis A drives 1 N*m up to 200 rad/s in 2 s (it draws int 100 t dt = 200 J) while a load
    # drives axis B the same way against its 1 N*m (it regenerates 200 J); ideal motors and
    # drives. Each on its own link with a resistor: 200 J drawn and 200 J burnt. On a shared
    # link the two cancel at every instant: nothing drawn, nothing burnt.
    from ballscrew.axis.drive import drive_totals

    t = np.linspace(0.0, 2.0, 201)
    w = 100.0 * t
    motor, spec = (
        MotorConstants(1.0, phase_resistance=0.0),
        DriveSpec(efficiency=1.0, dc_link="resistor", shared=shared),
    )
    a = drive_energy(t, np.ones_like(t), w, motor, spec)
    b = drive_energy(t, -np.ones_like(t), w, motor, spec)
    totals = drive_totals([a, b])
    assert totals["dc_link_shared"] is shared
    # The trapezoid is exact for a power linear in time.
    if shared:
        assert totals["grid_energy_J"] == 0.0 and totals["burnt_J"] == 0.0
    else:
        assert totals["grid_energy_J"] == pytest.approx(200.0, rel=1e-12)
        assert totals["burnt_J"] == pytest.approx(200.0, rel=1e-12)


def test_the_motors_drag_adds_no_current_at_rest() -> None:
    # A planner's rounding leaves -3e-15 rad/s where the axis stands: no direction of motion,
    # so the iron drag (0.2 N*m) adds nothing to the zero torque there, and no copper loss.
    motor = MotorConstants(1.0, phase_resistance=1.0, iron_loss_torque=0.2)
    e = drive_energy([0.0, 5.0], [0.0, 0.0], [-3e-15, 3e-15], motor, DriveSpec(1.0))
    assert e.copper_loss == 0.0
    moving = drive_energy([0.0, 5.0], [0.0, 0.0], [10.0, 10.0], motor, DriveSpec(1.0))
    assert moving.copper_loss == pytest.approx(3.0 * 0.2**2 * 5.0, rel=1e-14)  # 3 R (T_fe/K_t)^2 t


# Pins written from the mutation run of 2026-12-05 (docs/mutation.md): each against a hand
# computation of the module docstring's formulas.


def test_the_torque_constant_falls_linearly_up_to_any_positive_rated_speed() -> None:
    from ballscrew.axis.drive import torque_constant_at

    # K_t0 = 2, K_t,r = 1.8 at 0.5 rad/s: half-way (0.25 rad/s) 1.9, beyond it 1.8.
    k = torque_constant_at([0.25, -0.5, 3.0], 2.0, 1.8, 0.5)
    assert k.tolist() == pytest.approx([1.9, 1.8, 1.8], rel=1e-15)
    with pytest.raises(BallScrewInputError, match="rated speed"):
        torque_constant_at([1.0], 2.0, 1.8, 0.0)


def test_an_inverters_efficiency_loss_below_one_watt_and_at_zero_efficiency() -> None:
    from ballscrew.axis.drive import inverter_loss_efficiency

    # Motoring at 0.5 W through 80 %: the link gives 0.5/0.8 = 0.625 W, 0.125 W lost;
    # regenerating 0.5 W: 0.5 * 0.2 = 0.1 W lost.
    loss = inverter_loss_efficiency([0.5, -0.5], 0.8)
    assert loss.tolist() == pytest.approx([0.125, 0.1], rel=1e-12)
    with pytest.raises(BallScrewInputError, match="drive_efficiency"):
        inverter_loss_efficiency([1.0], 0.0)


def test_the_inverter_loss_models_terms_not_given_are_zero() -> None:
    from ballscrew.axis.drive import inverter_loss

    # 3 A: P0 alone 5 W, k alone 2 V * 3 A = 6 W, r alone 0.5 ohm * 9 A^2 = 4.5 W.
    assert float(inverter_loss(3.0, standby=5.0)) == 5.0
    assert float(inverter_loss(3.0, per_ampere=2.0)) == 6.0
    assert float(inverter_loss(3.0, resistance=0.5)) == 4.5
    # The same through a drive whose machine file gives one term: 2 s at I = T/K_t = 3 A.
    motor = MotorConstants(1.0, phase_resistance=0.0)
    for spec, watts in ((DriveSpec(standby=5.0), 5.0), (DriveSpec(per_ampere=2.0), 6.0),
                        (DriveSpec(resistance=0.5), 4.5)):  # fmt: skip
        e = drive_energy([0.0, 2.0], [3.0, 3.0], [0.0, 0.0], motor, spec)
        assert e.drive_loss == pytest.approx(2.0 * watts, rel=1e-15)


def test_an_inverters_efficiency_applies_to_the_shaft_iron_and_copper_powers() -> None:
    # T = 1 N*m at 100 rad/s, drag 0.1 N*m, K_t = 1 N*m/A, R_ph = 1 ohm: I = 1.1 A,
    # P_el = 100 + 0.1 * 100 + 3 * 1.21 = 113.63 W; through 90 % for 2 s the drive loses
    # 2 * 113.63 * (1/0.9 - 1) = 25.2511 J. The powers are constant: the trapezoid is exact.
    motor = MotorConstants(1.0, phase_resistance=1.0, iron_loss_torque=0.1)
    e = drive_energy([0.0, 2.0], [1.0, 1.0], [100.0, 100.0], motor,
                     DriveSpec(efficiency=0.9, dc_link="resistor"))  # fmt: skip
    assert e.copper_loss == pytest.approx(2.0 * 3.63, rel=1e-12)  # the drag adds to T
    assert e.drive_loss == pytest.approx(2.0 * 113.63 * (1.0 / 0.9 - 1.0), rel=1e-12)
    assert e.grid == pytest.approx(2.0 * 113.63 / 0.9, rel=1e-12)


def test_a_regenerative_link_nets_what_it_returns() -> None:
    # 1 kW for 1 s drawn, 600 W for 1 s returned: 400 J net from the grid.
    f = dc_link_flows([0, 1, 1, 2], [1000, 1000, -600, -600], "regenerative")
    assert (f.drawn, f.returned, f.grid) == (1000.0, 600.0, 400.0)


def test_a_storage_takes_small_steps_and_alternating_runs() -> None:
    # 1 J into a 10 J storage is kept; 0.8 J into a 0.5 J one fills it and burns 0.3 J.
    assert dc_link_flows([0, 1], [-1.0, -1.0], "storage", 10.0).stored == 1.0
    small = dc_link_flows([0, 1], [-0.8, -0.8], "storage", 0.5)
    assert (small.stored, small.burnt) == pytest.approx((0.5, 0.3), rel=1e-12)
    # Regenerate 500 J, draw 800 J, regenerate 200 J into 300 J: 200 J burnt at the first
    # run, 800 - 300 = 500 J drawn at the second, 200 J left stored after the third.
    t = [0.0, 1.0, 1.0, 2.0, 2.0, 3.0]
    f = dc_link_flows(t, [-500.0, -500.0, 800.0, 800.0, -200.0, -200.0], "storage", 300.0)
    assert (f.drawn, f.burnt, f.stored) == (500.0, 200.0, 200.0)


def test_the_totals_of_one_axis_are_its_own_figures() -> None:
    from ballscrew.axis.drive import drive_totals

    t = np.linspace(0.0, 2.0, 201)
    motor = MotorConstants(1.0, phase_resistance=0.5)
    for shared in (False, True):
        spec = DriveSpec(efficiency=1.0, dc_link="resistor", shared=shared)
        e = drive_energy(t, np.ones_like(t), 100.0 * t, motor, spec)
        totals = drive_totals([e])
        # 200 J on the shaft and 3 * 0.5 * 1 * 2 = 3 J of copper, nothing regenerated.
        assert totals["grid_energy_J"] == pytest.approx(203.0, rel=1e-12)
        assert totals["copper_loss_J"] == e.copper_loss and totals["dc_link_shared"] is shared
