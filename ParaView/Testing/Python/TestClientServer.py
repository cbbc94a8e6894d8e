"""Client-server: the plugin's filters on `pvserver` and on `mpirun -np 2 pvserver`
give what one process gives, bit for bit.

For one rank and for two, a pvserver is started with the plugin, the real
ParaView connects to it (--server-url) and plays the same steps: a Riemann
Metric reading the lens, then a Curvature Field (an image: each rank computes
its extent) or an Exponential Map (polylines: each rank its share of the
directions), saved in VTK's parallel formats (.pvti, .pvtp: one piece per
rank). Read back whole, the two-rank output equals the one-rank output, and
both equal the riemann command's. Neither server's log may hold an error.
"""

import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_outputs  # noqa: E402
from compare_outputs import check  # noqa: E402
import paraview_gui  # noqa: E402

DATA = os.environ["RIEMANN_DATA_DIR"]
RIEMANN = os.path.join(os.environ["RIEMANN_BIN_DIR"], "riemann")
METRIC = os.path.join(DATA, "metrics", "gaussian-lens.json")
CASES = [("RiemannCurvatureField", ["fields"], ".pvti", ".vti", ["ScalarCurvature", "Ricci", "SectionalMin"]),
         ("RiemannExponentialMap", ["expmap"], ".pvtp", ".vtp", None)]


def main():
    work = tempfile.mkdtemp(prefix="ParaViewClientServer-")
    for proxy, command, parallel, serial, names in CASES:
        reference = os.path.join(work, proxy + ".reference" + serial)
        subprocess.run([RIEMANN, *command, "--metric", METRIC, "--compress", "none", "-o", reference],
                       check=True, capture_output=True)
        outputs = {}
        for ranks in (1, 2):
            output = os.path.join(work, f"{proxy}-{ranks}{parallel}")
            server = paraview_gui.Server(work, ranks)
            steps = (paraview_gui.Steps()
                     .apply_source("RiemannMetricSource", DefinitionFile=METRIC)
                     .apply_filter(proxy)
                     .save_data(output))
            run = paraview_gui.run(steps, work, name=f"{proxy}-{ranks}", extra_args=["--server-url=" + server.url()])
            server_log = server.stop()
            where = f"{proxy} on {ranks} rank{'s' if ranks > 1 else ''}"
            check(run.returncode == 0, f"{where}: the client's script failed:\n{run.log[-2000:]}")
            errors = [line for line in server_log.splitlines() if " ERR| " in line]
            check(not errors and not run.errors(), f"{where}: errors: {(errors + run.errors())[:4]}")
            check(os.path.isfile(output), f"{where}: nothing saved")
            if os.path.isfile(output):
                outputs[ranks] = output
                for problem in compare_outputs.compare(output, reference, names):
                    check(False, f"{where}, against riemann {command[0]}: {problem}")
        if len(outputs) == 2:
            problems = compare_outputs.compare(outputs[2], outputs[1], names)
            for problem in problems:
                check(False, f"{proxy}: two ranks against one: {problem}")
            if not problems:
                print(f"{proxy}: two ranks' pieces equal one rank's and riemann {command[0]}'s")
    return compare_outputs.exit_status()


if __name__ == "__main__":
    sys.exit(main())
