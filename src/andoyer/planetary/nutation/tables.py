"""Fitted principal terms of the integrated nutation beside published rigid and non-rigid values."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer.catalogue.units import DAY, JULIAN_YEAR
from andoyer.perturbations.lunar_theory import check_span, delaunay_arguments, delaunay_rates
from andoyer.planetary.nutation.analytic import NutationSeries, nutation_series
from andoyer.planetary.nutation.fit import _large, _split, minimum_span
from andoyer.planetary.nutation.model import ARCSEC, H_MHB2000, MEAN_OBLIQUITY, PRINCIPAL_TERMS, _axis
from andoyer.planetary.nutation.numeric import _angle_blocks, _LeastSquares, _window
from andoyer.planetary.precession import check_dynamical_ellipticity

__all__ = ["IAU2000A", "REN2000", "REN2000_NODE", "WOOLARD1953", "numeric_terms", "terms_table"]

Array = NDArray[np.float64]

#: IAU 2000A (MHB2000, non-rigid) in-phase amplitudes ``(Δψ sin, Δε cos)`` of the principal terms,
#: arcsec (IERS Conventions 2010, Table 5.3a/5.3b; ``erfa.nut00a`` sums the same series).
IAU2000A = {
    "Ω": (-17.2064161, 9.2052331),
    "2Ω": (0.2074554, -0.0897492),
    "2(F−D+Ω)": (-1.3170906, 0.5730336),
    "2(F+Ω)": (-0.2276413, 0.0978459),
    "l′": (0.1475877, 0.0073871),
    "l": (0.0711159, -0.0006750),
}
#: REN-2000 (Souchay, Loysel, Kinoshita & Folgueira 1999, A&AS 135, 111), rigid Earth, **figure axis**:
#: in-phase amplitudes ``(Δψ sin, Δε cos)`` of the principal terms, arcsec. REN-2000 was computed
#: with ``H_D = 0.0032737548`` (Souchay & Kinoshita 1996, A&A 312, 1017, abstract), 1.22·10⁻⁵ below
#: MHB2000's ``H``: 0.2 mas on the 18.6-year ``Δψ``. The digits are not the paper's tables (images
#: online) but L. Petrov's machine-readable REN-2000, ``vtd/include/ren2000_heo.i`` in
#: github.com/nasa/sgdass (generated 2003-12-27, "REN2000 rigid Earth nutation"), which gives each
#: term as prograde (P) and retrograde (R) circular amplitudes ``PMC`` in picoradians with
#: ``ε₀ = 0.4090928041``: ``Δε = (P + R)``, ``Δψ sin ε₀ = (R − P)``. Summed over the entries of
#: the same argument: Ω P 39031706.5, R 5706463.6; 2Ω P −420537.3, R −17428.3; 2(F−D+Ω)
#: P 2573129.6, R 109529.8; 2(F+Ω) P 443685.4, R 16505.1; l′ P −121342.5, R 120688.5;
#: l P −67701.7, R 62986.9. Figure rather than momentum axis: the l term's ``Δε`` (−0.97 mas) is
#: an Oppolzer term, absent from the momentum axis.
REN2000 = {
    "Ω": (-17.2805921, 9.2279100),
    "2Ω": (0.2090296, -0.0903369),
    "2(F−D+Ω)": (-1.2774840, 0.5533382),
    "2(F+Ω)": (-0.2215116, 0.0949211),
    "l′": (0.1255036, -0.0001349),
    "l": (0.0677677, -0.0009725),
}
#: The 18.6-year term of :data:`REN2000` (kept for the earlier name).
REN2000_NODE = REN2000["Ω"]
#: Woolard's (1953) rigid-Earth series (rotation axis; Astron. Pap. Amer. Eph. 15, part 1, as in
#: the Explanatory Supplement 1961), in-phase ``(Δψ sin, Δε cos)``, arcsec. His ``H`` and lunar
#: mass (1/81.45) are older: compare ratios to the 18.6-year term.
WOOLARD1953 = {
    "Ω": (-17.2327, 9.2100),
    "2Ω": (0.2088, -0.0904),
    "2(F−D+Ω)": (-1.2729, 0.5522),
    "2(F+Ω)": (-0.2037, 0.0884),
    "l′": (0.1261, 0.0),
    "l": (0.0675, 0.0),
}


def numeric_terms(
    span: tuple[float, float],
    dynamical_ellipticity: float = H_MHB2000,
    axis: str = "figure",
    multipliers: ArrayLike | None = None,
    obliquity: float = MEAN_OBLIQUITY,
) -> tuple[Array, float]:
    """Fitted amplitudes (K, 4) of the integrated nutation over ``span``, and the precession rate (″/yr).

    The fit (:func:`fit_terms`) uses every term of the analytic series above
    0.02 mas as a regressor, so the principal terms do not absorb their
    neighbours; the span must reach :func:`minimum_span`. The precession rate
    is the frame's rate plus the fitted drift of ``ψ``.

    Parameters
    ----------
    span : (float, float)
        Julian years from J2000.
    dynamical_ellipticity : float
    axis : {"figure", "momentum", "rotation"}
    multipliers : array_like, shape (K, 5), optional
        Default: the :data:`PRINCIPAL_TERMS`.
    obliquity : float

    Returns
    -------
    amplitudes : numpy.ndarray, shape (K, 4)
        ``(ψs, ψc, εc, εs)``, arcsec.
    precession : float

    Examples
    --------
    >>> numeric_terms((0.0, 10.0))
    Traceback (most recent call last):
    ...
    ValueError: expected a span of at least 18.613 years to fit these terms, got 10.000
    """
    H = check_dynamical_ellipticity(dynamical_ellipticity)
    key = _axis(axis)
    eps0 = float(obliquity)
    t0, t1 = (float(v) for v in span)
    check_span(t0, t1)  # the user's span, before its middle is used as an epoch
    chosen = list(PRINCIPAL_TERMS.values()) if multipliers is None else multipliers
    wanted = np.atleast_2d(np.asarray(chosen, dtype=float))
    need = minimum_span(wanted, 0.5 * (t0 + t1))
    if not (t1 - t0 >= need * (1 - 1e-9)):
        msg = f"expected a span of at least {need:.3f} years to fit these terms, got {t1 - t0:.3f}"
        raise ValueError(msg)
    w = _window(t0, max(t1, t0 + minimum_span() * 1.001), H, eps0)
    middle = 0.5 * (t0 + t1)
    every, close = _split(_large(w.series), t1 - t0, middle, first=wanted)
    # Terms closer in frequency to a regressor than one cycle over the span cannot be told apart
    # from it (l′ and 2F − 2D + 2Ω − l′ differ by the Sun's perigee, 21 000 years): take them
    # out with the analytic series of this axis first.
    own = nutation_series(H, key, 0.5 * (w.t0 + w.end), eps0)
    amplitudes = np.array([own.term(tuple(row)) for row in close]).T.reshape(4, -1)
    prior = NutationSeries(close, *amplitudes, 0.0, H, eps0, key)
    # The terms are fitted on every eighth point of the span (with a constant and a drift), and
    # the drift of ψ once they are removed on every point: both from sums over the grid, a block
    # at a time. Centred times (any centre: the constant absorbs it).
    fit = _LeastSquares(2 + 2 * every.shape[0], 2)
    K = every.shape[0]
    sums = np.zeros(5)  # n, Σx, Σx², Σy, Σxy
    sin_sums = np.zeros((2, K))  # Σ sin θ, Σ x sin θ
    cos_sums = np.zeros((2, K))
    reference = None
    for first, grid, psi_grid, eps_grid in _angle_blocks(w, key):
        inside = grid <= t1 + 1e-12
        if not inside.any():
            break
        t = grid[inside]
        index = first + np.arange(t.size)
        known_psi, known_eps = prior(t)
        psi = psi_grid[inside] - known_psi * ARCSEC
        eps = eps_grid[inside] - known_eps * ARCSEC
        theta = delaunay_arguments(t) @ every.T
        sin, cos = np.sin(theta), np.cos(theta)
        x = t - middle
        rows = index % 8 == 0
        design = np.concatenate([np.ones((rows.sum(), 1)), x[rows, None], sin[rows], cos[rows]], 1)
        fit.add(design, np.stack([psi[rows], eps[rows]], -1))
        reference = float(psi[0]) if reference is None else reference
        y = psi - reference
        sums += (t.size, x.sum(), x @ x, y.sum(), x @ y)
        sin_sums += (sin.sum(0), x @ sin)
        cos_sums += (cos.sum(0), x @ cos)
    coefficients = fit.solve()
    fitted = np.stack([coefficients[2 : 2 + K, 0], coefficients[2 + K :, 0],
                       coefficients[2 + K :, 1], coefficients[2 : 2 + K, 1]], axis=-1)
    n, sx, sxx, sy, sxy = sums
    sy -= fitted[:, 0] @ sin_sums[0] + fitted[:, 1] @ cos_sums[0]
    sxy -= fitted[:, 0] @ sin_sums[1] + fitted[:, 1] @ cos_sums[1]
    drift = (n * sxy - sx * sy) / (n * sxx - sx * sx)
    return fitted[: wanted.shape[0]] / ARCSEC, (w.p + drift) / ARCSEC


def terms_table(
    span: tuple[float, float], dynamical_ellipticity: float = H_MHB2000, axis: str = "figure"
) -> dict:
    """The principal terms fitted over ``span`` beside the analytic series, REN-2000 and IAU 2000A.

    Parameters
    ----------
    span : (float, float)
        Julian years from J2000, at least :func:`minimum_span` long.
    dynamical_ellipticity : float
    axis : {"figure", "momentum", "rotation"}

    Returns
    -------
    dict
        ``terms``: one dict per principal term (``argument``, ``multipliers``,
        ``period_days``, fitted ``dpsi_sin``, ``dpsi_cos``, ``deps_cos``,
        ``deps_sin``, ``analytic_dpsi``, ``analytic_deps``, ``ren2000_dpsi``,
        ``ren2000_deps`` (figure axis only, else ``None``),
        ``iau2000a_dpsi``, ``iau2000a_deps``), arcsec; ``precession``: ″/yr.

    Examples
    --------
    >>> terms_table((0.0, 5.0), axis="momentum")
    Traceback (most recent call last):
    ...
    ValueError: expected a span of at least 18.613 years to fit these terms, got 5.000
    """
    H = check_dynamical_ellipticity(dynamical_ellipticity)
    key = _axis(axis)
    t0, t1 = (float(v) for v in span)
    fitted, precession = numeric_terms((t0, t1), H, key)
    series = nutation_series(H, key, 0.5 * (t0 + t1))
    rates = delaunay_rates(0.5 * (t0 + t1))
    rows = []
    for (name, n), amp in zip(PRINCIPAL_TERMS.items(), fitted, strict=True):
        analytic = series.term(n)
        ren = REN2000[name] if key == "figure" else (None, None)
        rows.append(
            {
                "argument": name,
                "multipliers": list(n),
                "period_days": float(2 * np.pi / abs(np.dot(n, rates)) * JULIAN_YEAR / DAY),
                "dpsi_sin": float(amp[0]),
                "dpsi_cos": float(amp[1]),
                "deps_cos": float(amp[2]),
                "deps_sin": float(amp[3]),
                "analytic_dpsi": analytic[0],
                "analytic_deps": analytic[2],
                "ren2000_dpsi": ren[0],
                "ren2000_deps": ren[1],
                "iau2000a_dpsi": IAU2000A[name][0],
                "iau2000a_deps": IAU2000A[name][1],
            }
        )
    return {"terms": rows, "precession": float(precession)}
