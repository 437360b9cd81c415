"""Write examples/ferry_pitch_log.csv: a synthetic 100-minute ferry voyage at 10 Hz.

Manoeuvring out of port, free sailing with occasional small pitch corrections, and
arrival with an astern manoeuvre, plus measurement noise of 0.05 % of design pitch. It
stands in for the seed's measured log (not published), to exercise the pitch-log tools.
"""

from pathlib import Path

import numpy as np

rng = np.random.default_rng(2009)
time = np.arange(0.0, 6000.0, 0.1)
# (time, pitch %) set points; linear ramps between them
points = [(0, 0), (60, 0), (120, 35), (400, 35), (460, 70), (900, 70), (1000, 100), (4200, 100),
          (4300, 60), (4900, 60), (5000, 25), (5400, 25), (5460, -55), (5560, -55), (5620, 0), (6000, 0)]
pitch = np.interp(time, *zip(*points, strict=True))
# free sailing: small corrections of 1-3 % every 30-120 s, held as steps
t = 1500.0
while t < 4100.0:
    step = rng.uniform(1.0, 3.0) * rng.choice([-1, 1])
    duration = rng.uniform(30.0, 120.0)
    pitch[(time >= t) & (time < t + duration)] += step
    t += duration + rng.uniform(30.0, 120.0)
pitch += rng.normal(0.0, 0.05, time.size)
out = Path(__file__).with_name("ferry_pitch_log.csv")
np.savetxt(out, np.column_stack([time, pitch]), delimiter=",", header="time,pitch", comments="", fmt="%.1f,%.3f")
print(f"wrote {out} ({time.size} samples)")
