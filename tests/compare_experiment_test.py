#!/usr/bin/env python3
"""Test of scripts/compare_experiment on synthetic data (issue 7).

The synthetic data and the expected results are written out here in closed
form, never computed with the script's own functions (a wrong formula in the
script must not also make the data it is tested on).  The model, from the
script's documentation and doc/examples/bench/README.md:

    V_syringe = Delta V^p(p) + p/(p + p0) V^p + Delta V_compliance(p),
    Delta V_compliance(p) = c0 + c1 p + c2 p^2  (least-squares quadratic),

with a known cavity curve Delta V^p(p) (cavity_curve), known c0, c1, c2
(compliance_exact: 2.5 + 31 p - 0.35 p^2 mm^3) and V^p, p0.  The script must
recover c0, c1, c2 from compliance data (exactly quadratic, and quadratic
plus a residual orthogonal to 1, p, p^2 whose R^2 and RMS are known), and
Delta V^p to round-off from the syringe volumes, both through its functions
and end to end through its command line.  Bad inputs must fail with a
message naming the file.

Markers (--markers): marker displacements sampled from the simulated curves
of tracked_points.csv, in other units and with a subset of the components,
must give differences of zero (to round-off through the
functions, to the printed digits in comparison.md); bad marker files and
markers the simulation does not track must fail with a message naming the
file.

Every check prints its verdict against its threshold (stderr).
Run: python3 tests/compare_experiment_test.py  (from any directory; the
script is found as ../scripts/compare_experiment next to this file).
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
import re  # noqa: E402
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
C0, C1, C2 = 2.5, 31.0, -0.35           # mm^3, mm^3/kPa, mm^3/kPa^2
COMPLIANCE = (C0, C1, C2)
P = np.linspace(0.0, 15.0, 61)          # measured pressures [kPa], 0.25 apart
P_SIM = np.linspace(0.0, 15.0, 21)      # simulated pressures, 0.75 apart
PSI = 6.894757293168361                 # kPa per psi (6894.757293168361 Pa)


def cavity_curve(p):
    """Known, smooth, nonlinear Delta V^p(p) [mm^3]."""
    return 175.0 * p + 1.8 * p**2 + 60.0 * np.sin(p / 4.0)


def compliance_exact(p):
    """Known syringe/tubing compliance Delta V_compliance(p) [mm^3], written
    out here (not the script's compliance_volume): 2.5 + 31 p - 0.35 p^2."""
    return C0 + C1 * p + C2 * p**2


def gas_volume(p):
    """Compressed air of the cavity, p/(p + p0) V^p [mm^3] (Eq. dV)."""
    return p / (p + P0) * CAVITY


def syringe_volume(p):
    """Forward model: what the syringe pump dispenses [mm^3]."""
    return cavity_curve(p) + gas_volume(p) + compliance_exact(p)


def orthogonal_residual(p):
    """A residual orthogonal, over the measured pressures P, to 1, p and p^2,
    so that a least-squares quadratic of compliance_exact + this must still
    return c0, c1, c2.  At P, x = 4p - 30 runs over the integers -m .. m
    (m = 30), and x^3 - a x is odd (orthogonal to 1 and x^2) and orthogonal
    to x for a = sum x^4 / sum x^2 = (3m^2 + 3m - 1)/5 = 557.8 (sum x^2 =
    m(m+1)(2m+1)/3, sum x^4 = m(m+1)(2m+1)(3m^2+3m-1)/15).  Amplitude
    0.103 mm^3 at most."""
    x = 4.0 * np.asarray(p, dtype=float) - 30.0
    return 1e-5 * (x**3 - 557.8 * x)


def write_csv(path, header, columns, comment="synthetic test data"):
    with open(path, "w") as f:
        f.write(f"# {comment}\n{','.join(header)}\n")
        for row in zip(*columns):
            f.write(",".join(repr(float(x)) for x in row) + "\n")


class Checks(unittest.TestCase):
    """Assertions that print their verdict against their threshold."""

    def say(self, text):
        """One verdict line under unittest's "test ... " line (stderr)."""
        if not getattr(self, "_said", False):
            self._said = True
            print(file=sys.stderr)
        print(f"    {text}", file=sys.stderr)

    def check(self, what, ok, detail=""):
        self.say(f"{what}: {'ok' if ok else 'FAIL'}")
        self.assertTrue(ok, f"{what} {detail}")

    def check_below(self, what, error, limit, unit="", strict=True):
        """error < limit (or <= if not strict)."""
        ok = bool(error < limit if strict else error <= limit)
        self.say(f"{what}: error {error:.3g}{unit} "
                 f"({'<' if strict else '<='} {limit:.3g}{unit}) "
                 f"{'ok' if ok else 'FAIL'}")
        self.assertTrue(ok, f"{what}: error {error:.6g} not "
                        f"{'<' if strict else '<='} {limit:.6g}")

    def check_close(self, what, actual, expected, rtol, atol, unit=""):
        """|actual - expected| <= atol + rtol |expected| everywhere (the
        test of np.testing.assert_allclose)."""
        actual = np.asarray(actual, dtype=float)
        expected = np.asarray(expected, dtype=float)
        self.assertEqual(actual.shape, expected.shape, what)
        error = np.abs(actual - expected)
        ok = bool(np.all(error <= atol + rtol * np.abs(expected)))
        limit = " + ".join([f"{atol:g}{unit}"] * (atol != 0)
                           + [f"{rtol:g} |expected|"] * (rtol != 0)) or "0"
        self.say(f"{what}: {'max ' * (error.size > 1)}error "
                 f"{np.max(error):.3g}{unit} (<= {limit}) "
                 f"{'ok' if ok else 'FAIL'}")
        self.assertTrue(ok, f"{what}: errors {error} above {atol:g} + "
                        f"{rtol:g} |{expected}|")


class Formulas(Checks):
    def test_compliance_volume_is_the_quadratic(self):
        self.check_close("compliance_volume(p) vs 2.5 + 31 p - 0.35 p^2",
                         ce.compliance_volume(P, COMPLIANCE),
                         compliance_exact(P), rtol=0, atol=1e-10,
                         unit=" mm^3")

    def test_compliance_fit_is_exact_for_quadratic_data(self):
        coefficients, r2, rms = ce.fit_compliance(P, compliance_exact(P))
        for name, unit, value, exact in zip(
                ("c0", "c1", "c2"), (" mm^3", " mm^3/kPa", " mm^3/kPa^2"),
                coefficients, COMPLIANCE):
            self.check_close(f"compliance {name} = {value:.6g}{unit} "
                             f"(exact {exact:g})", value, exact, rtol=1e-10,
                             atol=1e-10, unit=unit)
        # assertAlmostEqual(r2, 1, places=12): |r2 - 1| rounds to 0 at 12
        # decimal places
        self.check_below(f"R^2 = {r2:.15f} (exact 1)", abs(r2 - 1.0), 5e-13,
                         strict=False)
        self.check_below("RMS residual (exact 0)", rms, 1e-10, " mm^3")

    def test_compliance_fit_is_least_squares(self):
        # Data off the quadratic by a residual orthogonal to it: the fit
        # must still give c0, c1, c2, and R^2 and the RMS residual of that
        # residual, written out here from their definitions.
        r = orthogonal_residual(P)
        basis = np.column_stack([np.ones_like(P), P, P**2])
        self.check_below("test data: residual orthogonal to 1, p, p^2",
                         np.max(np.abs(basis.T @ r)), 1e-9)
        v = compliance_exact(P) + r
        coefficients, r2, rms = ce.fit_compliance(P, v)
        for name, unit, value, exact in zip(
                ("c0", "c1", "c2"), (" mm^3", " mm^3/kPa", " mm^3/kPa^2"),
                coefficients, COMPLIANCE):
            self.check_close(f"compliance {name} = {value:.6g}{unit} "
                             f"(exact {exact:g})", value, exact, rtol=1e-10,
                             atol=1e-10, unit=unit)
        rms_exact = np.sqrt(np.mean(r**2))
        r2_exact = 1.0 - np.sum(r**2) / np.sum((v - np.mean(v))**2)
        self.check_close(f"RMS residual {rms:.6g} mm^3 (exact "
                         f"{rms_exact:.6g})", rms, rms_exact, rtol=1e-9,
                         atol=0)
        self.check_close(f"R^2 = {r2:.12f} (exact {r2_exact:.12f})", r2,
                         r2_exact, rtol=0, atol=1e-12)

    def test_recovers_cavity_curve(self):
        scale = np.max(np.abs(cavity_curve(P)))
        fitted, _, _ = ce.fit_compliance(P, compliance_exact(P))
        for label, coefficients in (("fitted", fitted),
                                    ("exact", COMPLIANCE)):
            recovered = ce.correct_volume(syringe_volume(P), P, coefficients,
                                          CAVITY, P0)
            error = np.max(np.abs(recovered - cavity_curve(P)))
            self.check_below(f"Delta V^p recovered with the {label} "
                             f"compliance (curve scale {scale:.0f} mm^3)",
                             error, 1e-9 * scale, " mm^3")

    def test_without_compliance_only_gas_law(self):
        v = cavity_curve(P) + gas_volume(P)
        self.check_close("Delta V^p = V_syringe - p/(p + p0) V^p",
                         ce.correct_volume(v, P, None, CAVITY, P0),
                         cavity_curve(P), rtol=0, atol=1e-9, unit=" mm^3")

    def test_units_and_flow_rate(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "psi.csv")
            write_csv(path, ["time_min", "pressure_psi", "syringe_volume_ml"],
                      [P / 60, P / PSI, syringe_volume(P) / 1e3])
            p, v = ce.read_measurement(path)
            self.check_close("psi -> kPa", p, P, rtol=1e-14, atol=1e-14,
                             unit=" kPa")
            self.check_close("ml -> mm^3", v, syringe_volume(P), rtol=1e-14,
                             atol=0, unit=" mm^3")
            # volume from time: 6 ml/min = 100 mm^3/s for time_s seconds
            path = os.path.join(tmp, "time.csv")
            write_csv(path, ["time_s", "pressure [Pa]"], [P, 1000 * P])
            with self.assertRaisesRegex(ce.InputError, "time.csv.*flow-rate"):
                ce.read_measurement(path)
            self.say("time without --flow-rate: InputError naming time.csv: "
                     "ok")
            p, v = ce.read_measurement(path, flow_rate=6.0)
            self.check_close("6 ml/min * t = 100 mm^3/s * t", v, 100.0 * P,
                             rtol=1e-14, atol=0, unit=" mm^3")


class ScriptRun(Checks):
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
                  [1000 * pc, compliance_exact(pc) / 1000])
        self.runs = []
        for i, (p_name, p_factor) in enumerate([("pressure_kPa", 1.0),
                                                ("pressure_Pa", 1000.0),
                                                ("pressure_psi", 1.0)]):
            path = os.path.join(self.dir, f"run{i + 1}.csv")
            p = P if p_name != "pressure_psi" else P / PSI
            write_csv(path, ["time_s", p_name, "syringe_volume_mm3"],
                      [P, p * p_factor, syringe_volume(P)])
            self.runs.append(path)

    def test_end_to_end(self):
        out = os.path.join(self.dir, "out")
        result = self.run_cli("--simulation", self.sim, "--compliance",
                              self.compliance, "--run", self.runs[0],
                              "--run", *self.runs[1:], "--output-dir", out)
        self.check("exit status 0", result.returncode == 0, result.stderr)
        self.check("stdout reports R^2 = 1.000000",
                   "R^2 = 1.000000" in result.stdout, result.stdout)
        # the fitted compliance as printed (6 significant digits)
        match = re.search(r"c0 = (\S+) mm\^3, c1 = (\S+) mm\^3/kPa, "
                          r"c2 = (\S+) mm\^3/kPa\^2", result.stdout)
        self.check("stdout reports c0, c1, c2", match is not None,
                   result.stdout)
        for name, text, exact in zip(("c0", "c1", "c2"), match.groups(),
                                     COMPLIANCE):
            self.check_close(f"printed compliance {name} = {text} (exact "
                             f"{exact:g})", float(text), exact, rtol=1e-5,
                             atol=0)
        png = os.path.join(out, "pressure_volume.png")
        with open(png, "rb") as f:
            self.check("pressure_volume.png is a PNG",
                       f.read(8) == b"\x89PNG\r\n\x1a\n")
        with open(os.path.join(out, "comparison.md")) as f:
            rows = [line for line in f if line.startswith("| ")
                    and line[2].isdigit()]
        self.check(f"comparison.md has {len(rows)} rows (5)", len(rows) == 5)
        for row in rows:
            cells = [c.strip() for c in row.strip().strip("|").split("|")]
            p, sim, diff, pct = (float(cells[0]), float(cells[1]),
                                 float(cells[5]), float(cells[6]))
            exact = float(cavity_curve(p))
            self.check_below(f"p = {p:.2f} kPa: simulated {sim:.1f} mm^3 vs "
                             f"Delta V^p = {exact:.3f}", abs(sim - exact),
                             0.06, " mm^3", strict=False)
            self.check_below(f"p = {p:.2f} kPa: sim - meas = {cells[5]} "
                             f"mm^3 (exact 0)", abs(diff), 0.005, " mm^3",
                             strict=False)
            self.check_below(f"p = {p:.2f} kPa: sim - meas = {cells[6]} % "
                             f"(exact 0)", abs(pct), 0.005, " %",
                             strict=False)
        # the same, computed by the functions, to round-off
        p_sim, dv_sim, v0 = ce.read_simulation(self.sim)
        coefficients, _, _ = ce.fit_compliance(
            *ce.read_measurement(self.compliance))
        runs = [(p, ce.correct_volume(v, p, coefficients, v0, P0))
                for p, v in map(ce.read_measurement, self.runs)]
        for row in ce.comparison_rows(p_sim, dv_sim, runs):
            self.check_below(f"functions, p = {row[0]:.2f} kPa: sim - meas "
                             f"(exact 0)", abs(row[6]),
                             1e-9 * np.max(dv_sim), " mm^3")

    def test_without_compliance_says_so(self):
        result = self.run_cli("--simulation", self.sim, "--run",
                              self.runs[0])
        self.check("exit status 0", result.returncode == 0, result.stderr)
        self.check("stdout says NOT corrected",
                   "NOT corrected" in result.stdout, result.stdout)
        self.check("comparison.md written", os.path.exists(
            os.path.join(self.dir, "comparison.md")))

    def test_pressure_outside_simulation_warns(self):
        path = os.path.join(self.dir, "high.csv")
        p = np.linspace(0.0, 18.0, 37)
        write_csv(path, ["pressure_kPa", "syringe_volume_mm3"],
                  [p, syringe_volume(p)])
        result = self.run_cli("--simulation", self.sim, "--run", path)
        self.check("exit status 0", result.returncode == 0, result.stderr)
        self.check("warning: high.csv ... outside", re.search(
            "warning: .*high.csv.*outside", result.stderr) is not None,
            result.stderr)

    def assert_fails(self, name, header, columns, message, lines=None):
        path = os.path.join(self.dir, name)
        if lines is None:
            write_csv(path, header, columns)
        else:
            with open(path, "w") as f:
                f.write(lines)
        result = self.run_cli("--simulation", self.sim, "--run", path)
        check_failure(self, name, name, message, result)

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


def check_failure(test, name, named, message, result):
    """The script failed (non-zero exit) with a message naming the file
    `named` and matching `message`, without a traceback."""
    ok = (result.returncode != 0 and named in result.stderr
          and re.search(message, result.stderr) is not None
          and "Traceback" not in result.stderr)
    test.check(f"{name}: rejected (exit {result.returncode}), message names "
               f"{os.path.basename(named)} and matches /{message}/", ok,
               result.stderr)


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
                  [P, cavity_curve(P) + gas_volume(P)])
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
        for name, expected in (("tip_ux_mm", ("tip", 0, "mm")),
                               ("left_2_uZ [µm]", ("left_2", 2, "um")),
                               ("tip_uy", ("tip", 1, None)),
                               ("frame", None)):
            parsed = ce.split_marker_column(name)
            self.check(f"split_marker_column({name!r}) = {parsed} "
                       f"(expected {expected})", parsed == expected)

    def test_marker_named_like_a_quantity(self):
        path = os.path.join(self.dir, "port.csv")
        write_csv(path, ["pressure_kPa", "pressure_port_ux_mm"],
                  [np.array([0.0, 1.0]), np.array([0.0, 0.5])])
        p, markers = ce.read_markers(path)
        self.check(f"pressure column: {list(p)} (expected [0.0, 1.0])",
                   list(p) == [0.0, 1.0])
        u = list(markers.get("pressure_port", {}).get(0, []))
        self.check(f"marker pressure_port u_x: {u} (expected [0.0, 0.5])",
                   u == [0.0, 0.5])

    def test_differences_vanish(self):
        p_sim, points = ce.read_tracked(
            os.path.join(self.dir, "tracked_points.csv"))
        p, markers = ce.read_markers(self.markers)
        self.check_close("Pa -> kPa", p, P, rtol=1e-14, atol=1e-14,
                         unit=" kPa")
        self.check(f"side components {sorted(markers['side'])} (expected "
                   f"[0, 2])", sorted(markers["side"]) == [0, 2])
        self.check_close("side u_z, um -> mm", markers["side"][2],
                         simulated_curve("side", P)[:, 2], rtol=1e-13,
                         atol=1e-15, unit=" mm")
        rows = ce.marker_rows(p_sim, points, p, markers)
        self.check(f"{len(rows)} marker rows (6)", len(rows) == 6)
        for marker, pressure, sim, meas, diff, norm in rows:
            exact = simulated_curve(marker, [pressure])[0]
            self.check_close(f"{marker}, p = {pressure:.2f} kPa: simulated u",
                             sim, exact, rtol=0, atol=1e-12, unit=" mm")
            self.check_below(f"{marker}, p = {pressure:.2f} kPa: |sim - meas| "
                             f"(exact 0)", norm, 1e-12, " mm")
        self.check("side u_y not measured: NaN",
                   bool(np.isnan(rows[-1][4][1])))

    def marker_table_rows(self, path):
        with open(path) as f:
            return [[c.strip() for c in line.strip().strip("|").split("|")]
                    for line in f
                    if line.startswith("| tip ") or line.startswith("| side ")]

    def test_end_to_end(self):
        out = os.path.join(self.dir, "out")
        result = self.run_cli("--simulation", self.sim, "--run", self.run1,
                              "--markers", self.markers, "--output-dir", out)
        self.check("exit status 0", result.returncode == 0, result.stderr)
        self.check("warning: markers.csv ... ignored columns frame",
                   re.search("warning: .*markers.csv.*ignored columns frame",
                             result.stderr) is not None, result.stderr)
        for png in ("pressure_volume.png", "markers.png"):
            with open(os.path.join(out, png), "rb") as f:
                self.check(f"{png} is a PNG",
                           f.read(8) == b"\x89PNG\r\n\x1a\n")
        md = os.path.join(out, "comparison.md")
        with open(md) as f:
            text = f.read()
        for heading in ("# Simulated vs measured cavity volume change",
                        "## Marker displacements",
                        "tip: simulated at the surface node (60.00, 0.00, "
                        "11.50) mm; measured u_x, u_y, u_z"):
            self.check(f"comparison.md holds {heading!r}", heading in text)
        rows = self.marker_table_rows(md)
        self.check(f"{len(rows)} marker rows (6)", len(rows) == 6)
        for row in rows:
            p = float(row[1])
            sim = [float(x) for x in row[2].split(",")]
            self.check_close(f"{row[0]}, p = {p:.2f} kPa: simulated u as "
                             f"printed", sim, simulated_curve(row[0], [p])[0],
                             rtol=0, atol=6e-4, unit=" mm")
            diffs = [abs(float(x)) for x in row[4].split(",")
                     if x.strip() != "–"]
            self.check_below(f"{row[0]}, p = {p:.2f} kPa: sim - meas "
                             f"{row[4]} (exact 0)", max(diffs), 5e-4, " mm",
                             strict=False)
            self.check_below(f"{row[0]}, p = {p:.2f} kPa: |sim - meas| "
                             f"{row[5]} (exact 0)", float(row[5]), 5e-4,
                             " mm", strict=False)
        self.check("side u_y printed as –", [
            r[4].split(",")[1].strip() for r in rows if r[0] == "side"]
            == ["–"] * 3)

    def test_markers_without_runs(self):
        result = self.run_cli("--simulation", self.sim, "--markers",
                              self.markers)
        self.check("exit status 0", result.returncode == 0, result.stderr)
        with open(os.path.join(self.dir, "comparison.md")) as f:
            self.check("comparison.md starts with the marker heading",
                       f.read().startswith(
                           "# Simulated vs measured marker displacements"))
        self.check("no pressure_volume.png", not os.path.exists(
            os.path.join(self.dir, "pressure_volume.png")))
        # neither --run nor --markers: a usage error
        result = self.run_cli("--simulation", self.sim)
        self.check(f"neither --run nor --markers: exit {result.returncode} "
                   f"(2), message names --run", result.returncode == 2
                   and "--run" in result.stderr, result.stderr)

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
        check_failure(self, name, tracked or name, message, result)
        self.check(f"{name}: nothing written", not os.path.exists(
            os.path.join(self.dir, "bad")))

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
