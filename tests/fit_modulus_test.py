#!/usr/bin/env python3
"""Test of scripts/compare_experiment --fit-modulus against softopt itself.

The "measured" curve is made by the simulation, not by the fitting code's
formula: softopt analyzes a thick sphere octant (meshes/sphere_octant.geo,
radii 10 and 20 mm, 5 mm mesh, 150 kPa, nu = 0.49; the cavity grows by half
its volume, well into the nonlinear range) twice, at E = 1.2 MPa and at
E = 0.9 MPa, along different load steps (20 and 24).  (The coarse actuator
of tests/actuator_coarse.prm takes about 50 s for 20 steps, too long for
two runs in one test.)  The E = 0.9 load path becomes a synthetic
bench run through the forward model of the script's documentation (no
syringe compliance, so the compliance run dispenses nothing):

    V_syringe = Delta V^p + p/(p + p0) V^p,

with V^p the cavity volume at rest (row 0 of the E = 1.2 load path, which
the script uses).  compare_experiment --fit-modulus against the E = 1.2
simulation must then find E = 0.9 MPa within 1 %, use exactly the rows of
the E = 0.9 path whose Delta V lies within the E = 1.2 path's range, and
compare the fitted curve with the run to within 1 % in its table.  It must
find the run's parameters.prm next to load_path.csv or above it (as for
final_analysis/), take --simulated-modulus without one, refuse without
either, and refuse a --simulated-modulus that contradicts parameters.prm.

A Yeoh simulation (a third analyze run) must be refused with a message
naming the model and the parameter file, and a non-zero exit, writing
nothing.

Every check prints its verdict against its threshold (stderr).
Run: python3 tests/fit_modulus_test.py [SOFTOPT] [unittest names]
(SOFTOPT: the softopt executable, by default build/softopt of this source
tree; class FitModulus needs about 2 analyze runs, class NotNeoHookean 1).
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

import csv  # noqa: E402
import re  # noqa: E402
import shutil  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
import unittest  # noqa: E402

import numpy as np  # noqa: E402

SOURCE = os.path.normpath(os.path.join(os.path.dirname(
    os.path.abspath(__file__)), os.pardir))
SCRIPT = os.path.join(SOURCE, "scripts", "compare_experiment")
# The executable: the first argument if it is a file, else build/softopt.
if len(sys.argv) > 1 and os.path.isfile(sys.argv[1]):
    SOFTOPT = os.path.abspath(sys.argv.pop(1))
else:
    SOFTOPT = os.path.join(SOURCE, "build", "softopt")

P0 = 101.325                # kPa, the script's default p_0
E_SIM, E_CAST = 1.2, 0.9    # MPa: the simulation compared with, the "cast"
TOLERANCE = 1.0             # % error allowed on the fitted E


def sphere_case(output, material, increment):
    """A thick sphere octant (meshes/sphere_octant.geo, inner radius 10 mm,
    outer 20 mm, 5 mm mesh: a few seconds) inflated to 150 kPa in equal
    load increments, with the given lines of subsection Material; as a
    parameter file (the layout of tests/sphere_case.sh)."""
    material = "".join(f"  set {line}\n" for line in material)
    return f"""set Output directory = {output}
set Print timings = false
subsection Output
  set VTU output = none
end
subsection Geometry
  set Mesh file = sphere_octant.geo
  set Mesh size = 5
  set Mesh parameters = A: 10; B: 20
  set Dirichlet boundaries = 1: x; 2: y; 3: z
  set Pressure boundary ids = 4
  set Design boundary ids = 5
end
subsection Material
{material}end
subsection Loading
  set Pressure = 150
  set Initial load increment = {increment}
  set Maximum load increment = {increment}
end
"""


def analyze(folder, name, material, increment):
    """softopt analyze of the sphere case in folder; the folder of its
    results."""
    shutil.copy(os.path.join(SOURCE, "meshes", "sphere_octant.geo"), folder)
    prm = os.path.join(folder, f"{name}.prm")
    output = os.path.join(folder, name)
    with open(prm, "w") as f:
        f.write(sphere_case(output, material, increment))
    start = time.time()
    result = subprocess.run([SOFTOPT, "analyze", prm], cwd=folder,
                            capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError(f"softopt analyze {name}.prm failed (exit "
                           f"{result.returncode}):\n{result.stdout}\n"
                           f"{result.stderr}")
    print(f"  softopt analyze {name}.prm: {time.time() - start:.1f} s",
          file=sys.stderr)
    return output


def load_path(folder):
    """Columns of a load_path.csv as float arrays, by name."""
    with open(os.path.join(folder, "load_path.csv"), newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    return {name: np.array([float(r[j]) for r in rows[1:]])
            for j, name in enumerate(rows[0])}


def write_csv(path, header, columns):
    with open(path, "w") as f:
        f.write(f"# synthetic bench data from a softopt run\n"
                f"{','.join(header)}\n")
        for row in zip(*columns):
            f.write(",".join(repr(float(x)) for x in row) + "\n")


def check_softopt():
    if not os.access(SOFTOPT, os.X_OK):
        sys.exit(f"{__file__}: no softopt executable at {SOFTOPT}; build it "
                 f"or give its path as the first argument")


class Checks(unittest.TestCase):
    """Assertions that print their verdict against their threshold."""

    def say(self, text):
        if not getattr(self, "_said", False):
            self._said = True
            print(file=sys.stderr)
        print(f"    {text}", file=sys.stderr)

    def check(self, what, ok, detail=""):
        self.say(f"{what}: {'ok' if ok else 'FAIL'}")
        self.assertTrue(ok, f"{what} {detail}")

    def check_below(self, what, value, limit, unit=""):
        ok = bool(value < limit)
        self.say(f"{what}: {value:.3g}{unit} (< {limit:.3g}{unit}) "
                 f"{'ok' if ok else 'FAIL'}")
        self.assertTrue(ok, f"{what}: {value:.6g} not < {limit:.6g}")

    def run_cli(self, *args):
        return subprocess.run([sys.executable, SCRIPT, *args],
                              capture_output=True, text=True, cwd=self.dir)

    def check_refused(self, what, result, *patterns):
        """Non-zero exit, no traceback, stderr matching every pattern."""
        missing = [p for p in patterns if re.search(p, result.stderr) is None]
        self.check(f"{what}: refused (exit {result.returncode}), message "
                   f"matches {', '.join('/' + p + '/' for p in patterns)}",
                   result.returncode != 0 and not missing
                   and "Traceback" not in result.stderr, result.stderr)


class FitModulus(Checks):
    @classmethod
    def setUpClass(cls):
        check_softopt()
        cls.tmp = tempfile.TemporaryDirectory()
        cls.dir = cls.tmp.name
        material = ["Poisson's ratio = 0.49"]
        # The simulation at E_SIM in 20 steps, the "cast" at E_CAST in 24
        # (other pressures than the simulation's rows).
        cls.sim = analyze(cls.dir, "e_sim", material
                          + [f"Young's modulus = {E_SIM}"], 0.05)
        cls.cast = analyze(cls.dir, "e_cast", material
                           + [f"Young's modulus = {E_CAST}"], 1 / 24)
        sim, cast = load_path(cls.sim), load_path(cls.cast)
        cls.cavity = sim["cavity_volume_mm3"][0]
        cls.cavity_cast = cast["cavity_volume_mm3"][0]
        # The bench run: what the syringe dispenses for the cast's path.
        p, dv = cast["pressure_kPa"], cast["delta_volume_mm3"]
        cls.run_csv = os.path.join(cls.dir, "run1.csv")
        write_csv(cls.run_csv, ["pressure_kPa", "syringe_volume_mm3"],
                  [p, dv + p / (p + P0) * cls.cavity])
        cls.compliance = os.path.join(cls.dir, "compliance.csv")
        pc = np.linspace(0.0, 15.0, 16)
        write_csv(cls.compliance, ["pressure_kPa", "syringe_volume_mm3"],
                  [pc, np.zeros_like(pc)])
        # Rows of the cast's path within the simulated range of Delta V.
        dv_sim = sim["delta_volume_mm3"]
        cls.inside = int(np.count_nonzero((dv >= dv_sim.min())
                                          & (dv <= dv_sim.max())))
        cls.rows = p.size

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def fit(self, simulation, *extra, output="out"):
        return self.run_cli("--simulation", simulation, "--compliance",
                            self.compliance, "--run", self.run_csv,
                            "--fit-modulus", *extra, "--output-dir", output)

    def fitted(self, text):
        match = re.search(r"fitted E = (\S+) MPa \(simulated (\S+) MPa, "
                          r"scale (\S+)\), RMS residual (\S+) kPa \((\S+) % "
                          r"of the pressure range\) over (\d+) points of "
                          r"(\d+) runs?", text)
        self.check("report line 'fitted E = ... over N points of M run(s)'",
                   match is not None, text)
        return (float(match.group(1)), match.group(2), float(match.group(3)),
                float(match.group(4)), float(match.group(5)),
                int(match.group(6)), int(match.group(7)))

    def check_modulus(self, what, E):
        error = 100.0 * abs(E - E_CAST) / E_CAST
        ok = error < TOLERANCE
        self.say(f"{what}: fitted E {E:.4f} MPa (exact {E_CAST}), error "
                 f"{error:.2g} % (< {TOLERANCE:g} %) "
                 f"{'ok' if ok else 'FAIL'}")
        self.assertTrue(ok, f"{what}: fitted E {E} MPa, error {error} %")

    def test_fit_recovers_modulus(self):
        self.check(f"test data: same mesh, same V^p ({self.cavity:.3f} vs "
                   f"{self.cavity_cast:.3f} mm^3)",
                   self.cavity == self.cavity_cast)
        result = self.fit(os.path.join(self.sim, "load_path.csv"))
        self.check("exit status 0", result.returncode == 0, result.stderr)
        E, E_sim, scale, rms, relative, points, runs = \
            self.fitted(result.stdout)
        self.check_modulus("stdout", E)
        self.check(f"simulated E read from parameters.prm: {E_sim} MPa "
                   f"({E_SIM})", float(E_sim) == E_SIM)
        self.check(f"scale {scale} = E / E_sim to its 4 decimals",
                   abs(scale - E / E_SIM) < 1e-4)
        self.check(f"points used: {points} (the {self.inside} of "
                   f"{self.rows} rows of the E = {E_CAST} path within the "
                   f"simulated range of Delta V), of {runs} run (1)",
                   points == self.inside and runs == 1)
        self.check("parameters.prm named in the report",
                   os.path.join(self.sim, "parameters.prm") in result.stdout)
        self.check_below("relative RMS residual", relative, 0.5, " %")
        with open(os.path.join(self.dir, "out", "comparison.md")) as f:
            md = f.read()
        self.check_modulus("comparison.md", self.fitted(md)[0])
        # The table compares the simulation at the fitted E with the run.
        rows = [line for line in md.splitlines()
                if line.startswith("| ") and line[2].isdigit()]
        self.check(f"comparison.md has {len(rows)} table rows (5)",
                   len(rows) == 5)
        worst = max(abs(float(r.strip("|").split("|")[6])) for r in rows)
        self.check_below("table at the fitted E: largest |sim - meas|",
                         worst, TOLERANCE, " % of meas")
        with open(os.path.join(self.dir, "out", "pressure_volume.png"),
                  "rb") as f:
            self.check("pressure_volume.png is a PNG",
                       f.read(8) == b"\x89PNG\r\n\x1a\n")

    def test_parameters_found_from_final_analysis(self):
        # An optimize run's layout: <run>/final_analysis/load_path.csv.
        final = os.path.join(self.sim, "final_analysis")
        os.makedirs(final, exist_ok=True)
        shutil.copy(os.path.join(self.sim, "load_path.csv"), final)
        result = self.fit(os.path.join(final, "load_path.csv"),
                          output="final")
        self.check("final_analysis/: exit status 0", result.returncode == 0,
                   result.stderr)
        self.check_modulus("final_analysis/", self.fitted(result.stdout)[0])

    def test_without_parameters(self):
        # Three folders deep: nothing within two levels above holds a
        # parameters.prm.
        bare = os.path.join(self.dir, "bare", "a", "b")
        os.makedirs(bare, exist_ok=True)
        shutil.copy(os.path.join(self.sim, "load_path.csv"), bare)
        simulation = os.path.join(bare, "load_path.csv")
        result = self.fit(simulation, output="none")
        self.check_refused("no parameters.prm, no --simulated-modulus",
                           result, "load_path.csv", "no parameters.prm",
                           "--simulated-modulus")
        self.check("nothing written",
                   not os.path.exists(os.path.join(self.dir, "none")))
        result = self.fit(simulation, "--simulated-modulus", str(E_SIM),
                          output="given")
        self.check("--simulated-modulus 1.2: exit status 0",
                   result.returncode == 0, result.stderr)
        self.check("warning: neo-Hookean assumed (not checked)",
                   "not checked" in result.stderr, result.stderr)
        self.check_modulus("--simulated-modulus", self.fitted(
            result.stdout)[0])
        result = self.fit(os.path.join(self.sim, "load_path.csv"),
                          "--simulated-modulus", "1.0", output="contra")
        self.check_refused("--simulated-modulus 1.0 against parameters.prm "
                           "(1.2)", result, "parameters.prm",
                           "--simulated-modulus 1 MPa")


class NotNeoHookean(Checks):
    @classmethod
    def setUpClass(cls):
        check_softopt()
        cls.tmp = tempfile.TemporaryDirectory()
        cls.dir = cls.tmp.name
        cls.sim = analyze(cls.dir, "yeoh", [
            "Model = Yeoh", "Yeoh coefficients = 0.2, 0.01",
            "Poisson's ratio = 0.49"], 0.5)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_yeoh_refused(self):
        path = load_path(self.sim)
        p, dv = path["pressure_kPa"], path["delta_volume_mm3"]
        run = os.path.join(self.dir, "run1.csv")
        write_csv(run, ["pressure_kPa", "syringe_volume_mm3"],
                  [p, dv + p / (p + P0) * path["cavity_volume_mm3"][0]])
        simulation = os.path.join(self.sim, "load_path.csv")
        prm = os.path.join(self.sim, "parameters.prm")
        for extra in ([], ["--simulated-modulus", "1.2"]):
            result = self.run_cli("--simulation", simulation, "--run", run,
                                  "--fit-modulus", *extra,
                                  "--output-dir", "out")
            self.check_refused(f"Yeoh simulation{' ' if extra else ''}"
                               f"{' '.join(extra)}", result, "'Yeoh'",
                               re.escape(prm), "neo-Hookean")
            self.check("nothing written",
                       not os.path.exists(os.path.join(self.dir, "out")))
        # Without --fit-modulus the comparison itself still works.
        result = self.run_cli("--simulation", simulation, "--run", run,
                              "--output-dir", "plain")
        self.check("without --fit-modulus: exit status 0",
                   result.returncode == 0, result.stderr)


if __name__ == "__main__":
    unittest.main(verbosity=2)
