#!/usr/bin/env python3
"""Test of scripts/compare_experiment on synthetic data (issue 7).

A known cavity curve Delta V^p(p), a known compliance quadratic and the
ideal gas law give synthetic syringe volumes
    V_syringe = Delta V^p(p) + p/(p + p0) V^p + Delta V_compliance(p);
the script's correction must recover Delta V^p to round-off, both through its
functions and end to end through its command line.  Bad inputs must fail with
a message naming the file.

Markers (--markers): marker displacements sampled from the simulated curves
of tracked_points.csv, in other units and with a subset of the components,
must give differences of zero (to round-off through the
functions, to the printed digits in comparison.md); bad marker files and
markers the simulation does not track must fail with a message naming the
file.

Run: python3 tests/compare_experiment_test.py  (from any directory).
"""

import os
import subprocess
import sys


def _ensure_numpy():
    """CMake's Python3 may be an interpreter without numpy/matplotlib (e.g. a
    pyenv shim first in PATH); then rerun this test with the system one."""
    try:
        import numpy  # noqa: F401
        import matplotlib  # noqa: F401
        return
    except ImportError:
        pass
    system = "/usr/bin/python3"
    if (os.access(system, os.X_OK)
            and os.path.realpath(system) != os.path.realpath(sys.executable)
            and subprocess.call([system, "-c", "import numpy, matplotlib"],
                                stderr=subprocess.DEVNULL) == 0):
        os.execv(system, [system, os.path.abspath(__file__)] + sys.argv[1:])
    sys.exit(f"{__file__}: numpy and matplotlib are needed (Debian: "
             f"apt-get install python3-numpy python3-matplotlib)")


_ensure_numpy()

import importlib.machinery  # noqa: E402
import importlib.util  # noqa: E402
import tempfile  # noqa: E402
import unittest  # noqa: E402

import numpy as np  # noqa: E402

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                      os.pardir, "scripts", "compare_experiment")
SCRIPT = os.path.normpath(SCRIPT)


def load_script():
    loader = importlib.machinery.SourceFileLoader("compare_experiment",
                                                  SCRIPT)
    spec = importlib.util.spec_from_loader(loader.name, loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


ce = load_script()

P0 = 101.325                            # kPa
CAVITY = 14600.0                        # V^p [mm^3]
COMPLIANCE = (2.5, 31.0, -0.35)         # mm^3, mm^3/kPa, mm^3/kPa^2
P = np.linspace(0.0, 15.0, 61)          # measured pressures [kPa], 0.25 apart
P_SIM = np.linspace(0.0, 15.0, 21)      # simulated pressures, 0.75 apart


def cavity_curve(p):
    """Known, smooth, nonlinear Delta V^p(p) [mm^3]."""
    return 175.0 * p + 1.8 * p**2 + 60.0 * np.sin(p / 4.0)


def syringe_volume(p):
    """Forward model: what the syringe pump dispenses [mm^3]."""
    return (cavity_curve(p) + p / (p + P0) * CAVITY
            + ce.compliance_volume(p, COMPLIANCE))


def write_csv(path, header, columns, comment="synthetic test data"):
    with open(path, "w") as f:
        f.write(f"# {comment}\n{','.join(header)}\n")
        for row in zip(*columns):
            f.write(",".join(repr(float(x)) for x in row) + "\n")


class Formulas(unittest.TestCase):
    def test_compliance_fit_is_exact_for_quadratic_data(self):
        coefficients, r2, rms = ce.fit_compliance(
            P, ce.compliance_volume(P, COMPLIANCE))
        np.testing.assert_allclose(coefficients, COMPLIANCE, rtol=1e-10,
                                   atol=1e-10)
        self.assertAlmostEqual(r2, 1.0, places=12)
        self.assertLess(rms, 1e-10)

    def test_recovers_cavity_curve(self):
        coefficients, _, _ = ce.fit_compliance(
            P, ce.compliance_volume(P, COMPLIANCE))
        recovered = ce.correct_volume(syringe_volume(P), P, coefficients,
                                      CAVITY, P0)
        scale = np.max(np.abs(cavity_curve(P)))
        error = np.max(np.abs(recovered - cavity_curve(P)))
        print(f"\nmax recovery error {error:.3g} mm^3 "
              f"(curve scale {scale:.0f} mm^3)", file=sys.stderr)
        self.assertLess(error, 1e-9 * scale)

    def test_without_compliance_only_gas_law(self):
        v = cavity_curve(P) + P / (P + P0) * CAVITY
        np.testing.assert_allclose(ce.correct_volume(v, P, None, CAVITY, P0),
                                   cavity_curve(P), rtol=0, atol=1e-9)

    def test_units_and_flow_rate(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "psi.csv")
            write_csv(path, ["time_min", "pressure_psi", "syringe_volume_ml"],
                      [P / 60, P / 6.894757293168361, syringe_volume(P) / 1e3])
            p, v = ce.read_measurement(path)
            np.testing.assert_allclose(p, P, rtol=1e-14, atol=1e-14)
            np.testing.assert_allclose(v, syringe_volume(P), rtol=1e-14)
            # volume from time: 6 ml/min for time_s seconds
            path = os.path.join(tmp, "time.csv")
            write_csv(path, ["time_s", "pressure [Pa]"], [P, 1000 * P])
            with self.assertRaisesRegex(ce.InputError, "time.csv.*flow-rate"):
                ce.read_measurement(path)
            p, v = ce.read_measurement(path, flow_rate=6.0)
            np.testing.assert_allclose(v, 100.0 * P, rtol=1e-14)


class ScriptRun(unittest.TestCase):
    """A temporary folder, and the script run in it."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def run_cli(self, *args):
        return subprocess.run([sys.executable, SCRIPT, *args],
                              capture_output=True, text=True, cwd=self.dir)


class CommandLine(ScriptRun):
    def setUp(self):
        super().setUp()
        self.sim = os.path.join(self.dir, "load_path.csv")
        # load_path.csv in softopt's layout, with an extra trailing column.
        header = ("step,load_factor,pressure_kPa,cavity_volume_mm3,"
                  "delta_volume_mm3,design_mean_ux_mm,"
                  "design_mean_inward_radial_mm,newton_iterations,"
                  "residual_norm_N,at_target,objective").split(",")
        n = P_SIM.size
        dv = cavity_curve(P_SIM)
        write_csv(self.sim, header,
                  [np.arange(n), P_SIM / 15, P_SIM, CAVITY + dv, dv,
                   np.zeros(n), np.zeros(n), np.full(n, 3), np.full(n, 1e-9),
                   np.arange(n) == n - 1, np.zeros(n)])
        self.compliance = os.path.join(self.dir, "compliance.csv")
        pc = np.linspace(0.0, 20.0, 41)
        write_csv(self.compliance, ["pressure_Pa", "syringe_volume_ml"],
                  [1000 * pc, ce.compliance_volume(pc, COMPLIANCE) / 1000])
        self.runs = []
        for i, (p_name, p_factor) in enumerate([("pressure_kPa", 1.0),
                                                ("pressure_Pa", 1000.0),
                                                ("pressure_psi", 1.0)]):
            path = os.path.join(self.dir, f"run{i + 1}.csv")
            p = P if p_name != "pressure_psi" else P / 6.894757293168361
            write_csv(path, ["time_s", p_name, "syringe_volume_mm3"],
                      [P, p * p_factor, syringe_volume(P)])
            self.runs.append(path)

    def test_end_to_end(self):
        out = os.path.join(self.dir, "out")
        result = self.run_cli("--simulation", self.sim, "--compliance",
                              self.compliance, "--run", self.runs[0],
                              "--run", *self.runs[1:], "--output-dir", out)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("R^2 = 1.000000", result.stdout)
        png = os.path.join(out, "pressure_volume.png")
        with open(png, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        with open(os.path.join(out, "comparison.md")) as f:
            rows = [line for line in f if line.startswith("| ")
                    and line[2].isdigit()]
        self.assertEqual(len(rows), 5)
        for row in rows:
            cells = [c.strip() for c in row.strip().strip("|").split("|")]
            p, sim, diff, pct = (float(cells[0]), float(cells[1]),
                                 float(cells[5]), float(cells[6]))
            self.assertAlmostEqual(sim, float(cavity_curve(p)), delta=0.06)
            self.assertLessEqual(abs(diff), 0.005, row)
            self.assertLessEqual(abs(pct), 0.005, row)
        # the same, computed by the functions, to round-off
        p_sim, dv_sim, v0 = ce.read_simulation(self.sim)
        coefficients, _, _ = ce.fit_compliance(
            *ce.read_measurement(self.compliance))
        runs = [(p, ce.correct_volume(v, p, coefficients, v0, P0))
                for p, v in map(ce.read_measurement, self.runs)]
        for row in ce.comparison_rows(p_sim, dv_sim, runs):
            self.assertLess(abs(row[6]), 1e-9 * np.max(dv_sim))

    def test_without_compliance_says_so(self):
        result = self.run_cli("--simulation", self.sim, "--run",
                              self.runs[0])
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("NOT corrected", result.stdout)
        self.assertTrue(os.path.exists(
            os.path.join(self.dir, "comparison.md")))

    def test_pressure_outside_simulation_warns(self):
        path = os.path.join(self.dir, "high.csv")
        p = np.linspace(0.0, 18.0, 37)
        write_csv(path, ["pressure_kPa", "syringe_volume_mm3"],
                  [p, syringe_volume(p)])
        result = self.run_cli("--simulation", self.sim, "--run", path)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertRegex(result.stderr, "warning: .*high.csv.*outside")

    def assert_fails(self, name, header, columns, message, lines=None):
        path = os.path.join(self.dir, name)
        if lines is None:
            write_csv(path, header, columns)
        else:
            with open(path, "w") as f:
                f.write(lines)
        result = self.run_cli("--simulation", self.sim, "--run", path)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn(name, result.stderr)
        self.assertRegex(result.stderr, message)
        self.assertNotIn("Traceback", result.stderr)

    def test_bad_inputs(self):
        v = syringe_volume(P)
        self.assert_fails("missing.csv", ["time_s", "syringe_volume_ml"],
                          [P, v], "no pressure column")
        self.assert_fails("unitless.csv", ["pressure", "syringe_volume_ml"],
                          [P, v], "'pressure' does not state its unit")
        self.assert_fails("unitless_volume.csv", ["pressure_kPa", "volume"],
                          [P, v], "'volume' does not state its unit")
        self.assert_fails("badunit.csv", ["pressure_atm", "volume_ml"],
                          [P, v], "unknown unit")
        self.assert_fails("decreasing.csv", ["pressure_kPa",
                                             "syringe_volume_mm3"],
                          [P, v[::-1]], "decreases")
        self.assert_fails("text.csv", None, None, "line 3.*not a number",
                          lines="pressure_kPa,syringe_volume_ml\n0,0\n1,x\n")
        self.assert_fails("empty.csv", None, None, "empty", lines="# x\n")
        self.assert_fails("header_only.csv", None, None, "no data",
                          lines="pressure_kPa,syringe_volume_ml\n")


# Known displacement curves u(p) [mm] of two tracked points, and their nodes.
TRACKED = {"tip": (60.0, 0.0, 11.5), "side": (30.0, 0.0, 11.5)}


def marker_curve(name, p):
    """Known, smooth, nonlinear displacement (n, 3) [mm] at pressures p."""
    p = np.asarray(p, dtype=float)
    if name == "tip":
        return np.column_stack([0.05 * p + 0.002 * p**2, -0.004 * p,
                                0.04 * p + 0.1 * np.sin(p / 5.0)])
    return np.column_stack([0.01 * p, 0.003 * p**2,
                            0.12 * p - 0.002 * p**2])


def simulated_curve(name, p):
    """The simulation's view of marker_curve: tabulated at P_SIM, linear in
    between (what the script interpolates).  The measured pressures P hold
    every P_SIM, so markers sampled from this at P carry the same curve."""
    table = marker_curve(name, P_SIM)
    return np.column_stack([np.interp(p, P_SIM, table[:, c])
                            for c in range(3)])


class Markers(ScriptRun):
    def setUp(self):
        super().setUp()
        self.sim = os.path.join(self.dir, "load_path.csv")
        n = P_SIM.size
        dv = cavity_curve(P_SIM)
        write_csv(self.sim, ["step", "load_factor", "pressure_kPa",
                             "cavity_volume_mm3", "delta_volume_mm3"],
                  [np.arange(n), P_SIM / 15, P_SIM, CAVITY + dv, dv])
        # tracked_points.csv in softopt's layout
        header, columns = ["step", "load_factor", "pressure_kPa"], \
            [np.arange(n), P_SIM / 15, P_SIM]
        for name, X in TRACKED.items():
            u = marker_curve(name, P_SIM)
            for q, x in zip("XYZ", X):
                header.append(f"{name}_{q}_mm")
                columns.append(np.full(n, x))
            for c in range(3):
                header.append(f"{name}_u{'xyz'[c]}_mm")
                columns.append(u[:, c])
        write_csv(os.path.join(self.dir, "tracked_points.csv"), header,
                  columns)
        self.run1 = os.path.join(self.dir, "run1.csv")
        write_csv(self.run1, ["pressure_kPa", "syringe_volume_mm3"],
                  [P, cavity_curve(P) + P / (P + P0) * CAVITY])
        # The "video": pressure in Pa, tip in mm (all components), side in
        # micrometres (u_x, u_z only, bracket style), and a frame column.
        self.markers = os.path.join(self.dir, "markers.csv")
        tip, side = simulated_curve("tip", P), simulated_curve("side", P)
        write_csv(self.markers,
                  ["frame", "pressure_Pa", "tip_ux_mm", "tip_uy_mm",
                   "tip_uz_mm", "side_ux [um]", "side_uz [um]"],
                  [np.arange(P.size), 1000 * P, tip[:, 0], tip[:, 1],
                   tip[:, 2], 1000 * side[:, 0], 1000 * side[:, 2]])

    def test_column_names(self):
        self.assertEqual(ce.split_marker_column("tip_ux_mm"), ("tip", 0, "mm"))
        self.assertEqual(ce.split_marker_column("left_2_uZ [µm]"),
                         ("left_2", 2, "um"))
        self.assertEqual(ce.split_marker_column("tip_uy"), ("tip", 1, None))
        self.assertIsNone(ce.split_marker_column("frame"))

    def test_marker_named_like_a_quantity(self):
        path = os.path.join(self.dir, "port.csv")
        write_csv(path, ["pressure_kPa", "pressure_port_ux_mm"],
                  [np.array([0.0, 1.0]), np.array([0.0, 0.5])])
        p, markers = ce.read_markers(path)
        self.assertEqual(list(p), [0.0, 1.0])
        self.assertEqual(list(markers["pressure_port"][0]), [0.0, 0.5])

    def test_differences_vanish(self):
        p_sim, points = ce.read_tracked(
            os.path.join(self.dir, "tracked_points.csv"))
        p, markers = ce.read_markers(self.markers)
        np.testing.assert_allclose(p, P, rtol=1e-14, atol=1e-14)
        self.assertEqual(sorted(markers["side"]), [0, 2])
        np.testing.assert_allclose(markers["side"][2],
                                   simulated_curve("side", P)[:, 2],
                                   rtol=1e-13, atol=1e-15)
        rows = ce.marker_rows(p_sim, points, p, markers)
        self.assertEqual(len(rows), 6)
        for marker, pressure, sim, meas, diff, norm in rows:
            exact = simulated_curve(marker, [pressure])[0]
            np.testing.assert_allclose(sim, exact, rtol=0, atol=1e-12)
            self.assertLess(norm, 1e-12, (marker, pressure))
        self.assertTrue(np.isnan(rows[-1][4][1]))  # side u_y: not measured

    def marker_table_rows(self, path):
        with open(path) as f:
            return [[c.strip() for c in line.strip().strip("|").split("|")]
                    for line in f
                    if line.startswith("| tip ") or line.startswith("| side ")]

    def test_end_to_end(self):
        out = os.path.join(self.dir, "out")
        result = self.run_cli("--simulation", self.sim, "--run", self.run1,
                              "--markers", self.markers, "--output-dir", out)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertRegex(result.stderr, "warning: .*markers.csv.*ignored "
                         "columns frame")
        for png in ("pressure_volume.png", "markers.png"):
            with open(os.path.join(out, png), "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        md = os.path.join(out, "comparison.md")
        with open(md) as f:
            text = f.read()
        self.assertIn("# Simulated vs measured cavity volume change", text)
        self.assertIn("## Marker displacements", text)
        self.assertIn("tip: simulated at the surface node (60.00, 0.00, "
                      "11.50) mm; measured u_x, u_y, u_z", text)
        rows = self.marker_table_rows(md)
        self.assertEqual(len(rows), 6)
        for row in rows:
            p = float(row[1])
            sim = [float(x) for x in row[2].split(",")]
            np.testing.assert_allclose(sim, simulated_curve(row[0], [p])[0],
                                       rtol=0, atol=6e-4)
            for x in row[4].split(","):
                if x.strip() != "–":
                    self.assertLessEqual(abs(float(x)), 5e-4, row)
            self.assertLessEqual(float(row[5]), 5e-4, row)
        self.assertEqual([r[4].split(",")[1].strip() for r in rows
                          if r[0] == "side"], ["–"] * 3)

    def test_markers_without_runs(self):
        result = self.run_cli("--simulation", self.sim, "--markers",
                              self.markers)
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(os.path.join(self.dir, "comparison.md")) as f:
            self.assertTrue(f.read().startswith(
                "# Simulated vs measured marker displacements"))
        self.assertFalse(os.path.exists(
            os.path.join(self.dir, "pressure_volume.png")))
        # neither --run nor --markers: a usage error
        result = self.run_cli("--simulation", self.sim)
        self.assertEqual(result.returncode, 2)
        self.assertIn("--run", result.stderr)

    def assert_fails(self, name, header, columns, message, lines=None,
                     tracked=None):
        path = os.path.join(self.dir, name)
        if lines is None:
            write_csv(path, header, columns)
        else:
            with open(path, "w") as f:
                f.write(lines)
        args = ["--simulation", self.sim, "--markers", path]
        if tracked:
            args += ["--tracked", tracked]
        result = self.run_cli(*args, "--output-dir", "bad")
        self.assertNotEqual(result.returncode, 0)
        self.assertIn(tracked or name, result.stderr)
        self.assertRegex(result.stderr, message)
        self.assertNotIn("Traceback", result.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.dir, "bad")))

    def test_bad_marker_data(self):
        u = marker_curve("tip", P)[:, 0]
        self.assert_fails("unknown.csv", ["pressure_kPa", "tip_ux_mm",
                                          "nose_uz_mm"], [P, u, u],
                          "marker\\(s\\) nose not tracked .* tracks tip, side")
        self.assert_fails("unitless.csv", ["pressure_kPa", "tip_ux"], [P, u],
                          "'tip_ux' does not state its unit")
        self.assert_fails("inches.csv", ["pressure_kPa", "tip_ux_in"],
                          [P, u], "unknown unit 'in'")
        self.assert_fails("twice.csv", ["pressure_kPa", "tip_ux_mm",
                                        "tip_ux_um"], [P, u, 1000 * u],
                          "two columns for u_x of marker 'tip'")
        self.assert_fails("nopressure.csv", ["time_s", "tip_ux_mm"], [P, u],
                          "no pressure column")
        self.assert_fails("nomarker.csv", ["pressure_kPa", "frame"], [P, u],
                          "no marker displacement column")
        self.assert_fails("text.csv", None, None, "line 3.*not a number",
                          lines="pressure_kPa,tip_ux_mm\n0,0\n1,lost\n")
        self.assert_fails("norange.csv", ["pressure_kPa", "tip_ux_mm"],
                          [P + 20, u], "share no pressure range")
        self.assert_fails("ok.csv", ["pressure_kPa", "tip_ux_mm"], [P, u],
                          "no such file", tracked=os.path.join(
                              self.dir, "missing", "tracked_points.csv"))


if __name__ == "__main__":
    unittest.main(verbosity=2)
