# SPDX-License-Identifier: BSD-3-Clause
# coupled_run.py — gallery: the Python export of coupled_coils.bg (bgdraw
# coupled_coils.bg -o coupled_coils_model.py) run with SciPy with a load of 8 ohm
# instead of 2; prints t and both currents every 10 ms.
import coupled_coils_model as m

p = dict(m.PARAMS, R2=8.0)
t, y, out = m.simulate(t_end=0.1, dt=0.01, p=p, rtol=1e-10, atol=1e-12)
for k in range(len(t)):
    print("%g %.9f %.9f" % (t[k], out[0][k], out[1][k]))
