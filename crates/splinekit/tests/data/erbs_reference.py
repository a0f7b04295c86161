"""Reference values of the default ERBS B-function (φ(s) = exp(−(s−½)²/(s(1−s)))) and its
first three derivatives at 241 parameters, by 40-digit quadrature (mpmath). Writes
erbs_reference.json; run with `python3 erbs_reference.py` (needs mpmath)."""
import json
import mpmath as mp

mp.mp.dps = 40
half = mp.mpf(1) / 2


def phi(s):
    return mp.e ** (-(s - half) ** 2 / (s * (1 - s)))


S = mp.quad(phi, [0, half, 1])
rows = []
for i in range(241):
    # Dense in the middle, and close to both ends.
    t = mp.mpf(i) / 240 if 0 < i < 240 else (mp.mpf(1) / 512 if i == 0 else 1 - mp.mpf(1) / 512)
    t = mp.mpf(float(t) + 1e-9 * (i % 7))  # off the cell grid, exactly representable
    b = mp.quad(phi, [0, t]) / S if t <= half else 1 - mp.quad(phi, [t, 1]) / S
    d1 = phi(t) / S
    d2 = mp.diff(phi, t, 1) / S
    d3 = mp.diff(phi, t, 2) / S
    rows.append([float(t)] + [mp.nstr(x, 25) for x in (b, d1, d2, d3)])
json.dump({"S": mp.nstr(S, 25), "rows": rows}, open("erbs_reference.json", "w"), indent=0)
