"""How long riemann-studio's Cancel takes to stop a long job (issue 32).

Run in the app:  xvfb-run -a build/bin/riemann-studio --size 640x400 \
    --script Testing/Benchmarks/studio_cancel_latency.py --exit

A 200,000-direction conjugate locus of the Gaussian bump (the case the issue
reported: "Cancelled" at once, the job running ~5 min more) is started, left
to run for a few seconds, cancelled; the time until no job runs is printed,
for several waits. A measurement, not a test: the machine's load moves it.
"""
import time

import studio

studio.metric('{"type": "graph", "gaussians": [{"amplitude": 1.0, "center": [0, 0, 0], '
              '"sigma": [0.5, 0.5, 0.5]}]}')
studio.render()
for wait in (2.0, 6.0, 12.0):
    item = studio.add("conjugate-locus", NumberOfDirections=200000)
    studio.wait(wait)
    running = studio.running()
    cancelled = time.monotonic()
    studio.cancel()
    while studio.running() > 0:
        studio.wait(0.002)
    print("cancel after %4.1f s (%d job(s) running): stopped in %.3f s"
          % (wait, running, time.monotonic() - cancelled))
    studio.remove(item)
