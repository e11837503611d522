"""runs.py and figures.py on a results folder written here: dx from summary.json, scales from
the case, which probes are loads, a force probe's component, and the refusals of bad input."""
import json
import math
import sys
import tempfile
import unittest
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
from sluice_loads.figures import Options, run_figures  # noqa: E402
from sluice_loads.runs import BadInput, case_scales, open_run, parse_scale  # noqa: E402

CASE = """[case]
name = "t"
dimension = 2
[fluid]
rho0 = 1000.0
gravity = [0.0, -10.0]
[particles]
dx = 0.05
[[blocks]]
lo = [0.0, 0.0]
hi = [0.5, 0.4]
[[blocks]]
lo = [0.5, 0.0]
hi = [1.0, 0.1]
[[probes]]
name = "sensor"
type = "pressure"
position = [1.0, 0.02]
diameter = 0.01
[[probes]]
name = "wall"
type = "force"
face = "x-"
"""


class ResultsFolder(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        d = Path(self.tmp.name)
        (d / "case.toml").write_text(CASE)
        run = d / "run"
        (run / "probes").mkdir(parents=True)
        (run / "summary.json").write_text(json.dumps({
            "case": "t", "dimension": 2, "source_file": str(d / "case.toml"),
            "extra": {"neighbours": {"crowded_below": 0.0125}}}))
        t = np.linspace(0.0, 1.0, 1001)
        tri = np.interp(t, [0.0, 0.4, 0.5, 0.6, 1.0], [0.0, 0.0, 1.0, 0.0, 0.0])
        np.savetxt(run / "probes" / "sensor.csv", np.c_[t, 8000.0 * tri], delimiter=",",
                   header="time_s,pressure_Pa", comments="")
        np.savetxt(run / "probes" / "wall.csv", np.c_[t, -900.0 * tri, 5.0 * tri],
                   delimiter=",", header="time_s,Fx_N,Fy_N", comments="")
        np.savetxt(run / "probes" / "front.csv", np.c_[t, t], delimiter=",",
                   header="time_s,front_x_m", comments="")
        (run / "probes" / "empty.csv").write_text("time_s,pressure_Pa\n")
        self.run_dir = run

    def tearDown(self):
        self.tmp.cleanup()

    def test_folder_case_and_scales(self):
        run = open_run(self.run_dir)
        self.assertEqual(run.dx, 0.025)  # twice crowded_below, not the case's 0.05
        self.assertEqual((run.scales.H, run.scales.g, run.scales.rho0), (0.4, 10.0, 1000.0))
        self.assertEqual(run.probes["sensor"].kind, "area")
        self.assertEqual(run.probes["wall"].default_component(), "-Fx")  # into face x-
        self.assertNotIn("front", run.probes)

    def test_figures_in_si_and_scaled(self):
        run = open_run(self.run_dir)
        sensor, wall = run_figures(run, ["sensor", "wall"], Options(filter_s=0.0,
                                                                      smooth_s=0.0))
        self.assertEqual(sensor["peak_raw"], 8000.0)
        self.assertAlmostEqual(sensor["peak_raw_scaled"], 2.0)  # rho g H = 4000 Pa
        self.assertAlmostEqual(sensor["t_contact"], 0.403)  # first sample above 200 Pa
        self.assertEqual(wall["signal"], "-Fx")
        self.assertEqual(wall["peak_raw"], 900.0)
        self.assertAlmostEqual(wall["peak_raw_scaled"], 900.0 / 800.0)  # rho g H^2/2
        self.assertEqual(wall["unit"], "N/m")
        # to the record's end (window 0): the whole triangle less the part before contact
        whole = run_figures(run, ["sensor"], Options(window_star=0.0))[0]
        self.assertAlmostEqual(whole["impulse"], 800.0 - 0.5 * 0.003 * 240.0, places=9)
        self.assertEqual(whole["t_window_end"], 1.0)
        fy = run_figures(run, ["wall"], Options(component="Fy", contact=0.001))[0]
        self.assertEqual(fy["peak_raw"], 5.0)
        late = run_figures(run, ["sensor"], Options(t_from=0.7))[0]
        self.assertTrue(math.isnan(late["peak_raw"]))  # no contact after 0.7 s

    def test_bad_input_names_what_is_wrong(self):
        run = open_run(self.run_dir)
        for args, named in ((["nope"], "'nope'"), (["front"], "front.csv"),
                            (["empty"], "empty.csv")):
            with self.assertRaises(BadInput) as e:
                run_figures(run, args, Options())
            self.assertIn(named, str(e.exception))
        with self.assertRaises(BadInput) as e:
            run_figures(run, ["wall"], Options(component="Fz"))
        self.assertIn("Fz", str(e.exception))
        with self.assertRaises(BadInput) as e:
            open_run(self.run_dir.parent / "missing")
        self.assertIn("missing", str(e.exception))
        with self.assertRaises(BadInput):
            parse_scale("1000,9.81")

    def test_scales_from_a_case_and_by_hand(self):
        case = {"case": {"dimension": 3}, "fluid": {"gravity": [0.0, 0.0, -9.81]},
                "blocks": [{"lo": [0, 0, 0.1], "hi": [1, 1, 0.7]}]}
        sc = case_scales(case)
        self.assertAlmostEqual(sc.H, 0.6)
        self.assertEqual((sc.g, sc.rho0), (9.81, 1000.0))
        sc = parse_scale("998,9.8,0.25")
        self.assertEqual((sc.rho0, sc.g, sc.H), (998.0, 9.8, 0.25))


if __name__ == "__main__":
    unittest.main()
