"""Discretisation uncertainty from three resolutions: Roache's grid convergence index (Roache
1998, "Verification and validation in computational science and engineering", ch. 5) in the
procedure of Celik et al. (2008), "Procedure for estimation and reporting of uncertainty due to
discretization in CFD applications", J. Fluids Eng. 130, 078001.

With f1, f2, f3 the fine, medium and coarse values, h1 < h2 < h3 their spacings, r21 = h2/h1,
r32 = h3/h2, e21 = f2 - f1 and e32 = f3 - f2:
  - the observed order p solves p = |ln|e32/e21| + q(p)| / ln r21 with
    q(p) = ln((r21^p - s) / (r32^p - s)), s = sign(e32/e21) (their eqs. 3a-c; q = 0 when
    r21 = r32, so p = |ln|e32/e21|| / ln r);
  - the extrapolated value f_ext = (r21^p f1 - f2) / (r21^p - 1) (their eq. 4);
  - the fine-grid index GCI = Fs |e21/f1| / (r21^p - 1), Fs = 1.25 for three grids (eq. 5).
The order used in the GCI is at most the scheme's formal order (an option; 2 for SPH's kernel
approximation): a larger observed order from three values claims more than the scheme gives.
What the ladder is:
  - "flat": both changes within `flat` (1 %) of f1: converged, too little change to read p;
  - "oscillatory": e32/e21 < 0: no order and no extrapolation;
  - "diverging": |e21| >= |e32|, the change does not shrink with refinement: not in the
    asymptotic range (order returned negative, nothing extrapolated);
  - "monotone": p, f_ext and the GCI.
"""
from __future__ import annotations

import math

SAFETY = 1.25
FORMAL_ORDER = 2.0
FLAT = 0.01


def observed_order(e21: float, e32: float, r21: float, r32: float) -> float:
    """Celik et al.'s eq. 3 for a monotone ladder (e32/e21 > 0, |e32| > |e21|): closed form
    for a constant ratio, else the fixed-point iteration; NaN when it does not settle."""
    ratio = abs(e32 / e21)
    if abs(r21 - r32) <= 1e-12 * r21:
        return abs(math.log(ratio)) / math.log(r21)
    s = 1.0 if e32 / e21 > 0 else -1.0
    p = abs(math.log(ratio)) / math.log(r21)
    for _ in range(200):
        try:
            q = math.log((r21**p - s) / (r32**p - s))
        except (ValueError, ZeroDivisionError, OverflowError):
            return math.nan
        nxt = abs(math.log(ratio) + q) / math.log(r21)
        if abs(nxt - p) < 1e-12 * max(1.0, p):
            return nxt
        p = nxt
    return math.nan


def three_grid(f1: float, f2: float, f3: float, r21: float = 2.0, r32: float = 2.0,
               safety: float = SAFETY, formal_order: float = FORMAL_ORDER,
               flat: float = FLAT) -> dict:
    """kind, order (observed), f_ext and gci_fine (a fraction of |f1|) of a three-level
    ladder, fine value first; NaN where the kind gives none."""
    nan = math.nan
    e21, e32 = f2 - f1, f3 - f2
    res = {"order": nan, "f_ext": nan, "gci_fine": nan, "kind": ""}
    if max(abs(e21), abs(e32)) <= flat * abs(f1):
        res["kind"] = "flat"
        return res
    if e21 == 0.0:  # the fine step did not move at all, the coarse one did
        res.update(kind="monotone", order=math.inf, f_ext=f1, gci_fine=0.0)
        return res
    if e32 / e21 < 0:
        res["kind"] = "oscillatory"
        return res
    if abs(e21) >= abs(e32):
        res["kind"] = "diverging"
        res["order"] = -abs(math.log(abs(e32 / e21))) / math.log(r21)
        return res
    p = observed_order(e21, e32, r21, r32)
    res["kind"] = "monotone"
    if not math.isfinite(p):
        return res
    res["order"] = p
    q = r21**p
    res["f_ext"] = (q * f1 - f2) / (q - 1.0)
    pc = min(p, formal_order)
    res["gci_fine"] = safety * abs(e21 / f1) / (r21**pc - 1.0) if f1 else nan
    return res


def verdict(res: dict, formal_order: float = FORMAL_ORDER, flat: float = FLAT) -> str:
    """A sentence on what the ladder says, for the table's last column."""
    kind, p = res["kind"], res["order"]
    if kind == "flat":
        return f"converged: both changes within {100 * flat:g} % of the fine value"
    if kind == "oscillatory":
        return "oscillates: no observed order, no extrapolation"
    if kind == "diverging":
        return "not in the asymptotic range: the change grows with refinement"
    if not math.isfinite(p):
        return "monotone, but no observed order found (unequal ratios): no GCI"
    if p > 2.0 * formal_order or p < 0.5 * formal_order:
        capped = f"; GCI with p = {formal_order:g}" if p > formal_order else ""
        return (f"monotone, but p = {p:.2f} is far from the formal order {formal_order:g}: "
                f"not shown to be in the asymptotic range{capped}")
    if p > formal_order:
        return f"monotone, order near the formal {formal_order:g} (GCI with p = {formal_order:g})"
    return f"monotone, order near the formal {formal_order:g}"
