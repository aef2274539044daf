"""The table of docs/catalogue.md, made from the catalogue (the page must hold these rows)."""

from __future__ import annotations

from andoyer import catalogue

HEADER = "| body | GM (km³/s²) | R (km) | J₂ | C₂₂ | C/MR² | H | α₀, δ₀ (°) | Ẇ (°/d) | a | e | i (°) |"


def cell(q) -> str:
    if q is None:
        return ""
    text = f"{q.value:.10g}"
    if q.uncertainty:
        text += f" ± {q.uncertainty:.2g}"
    return text + (" †" if "UNVERIFIED" in q.note else "")


def rows() -> list[str]:
    out = [HEADER, "|" + "---|" * 12]
    for name in catalogue.names():
        b = catalogue.get(name)
        a = "" if b.semi_major_axis is None else f"{b.semi_major_axis.value:.10g} {b.semi_major_axis.unit}"
        pole = "" if b.pole_ra is None else f"{b.pole_ra.value:g}, {b.pole_dec.value:g}"
        cells = [b.name, cell(b.gm), cell(b.radius), cell(b.j2), cell(b.c22), cell(b.moment_of_inertia)]
        cells += [cell(b.dynamical_ellipticity), pole, cell(b.rotation_rate), a, cell(b.eccentricity)]
        cells += [cell(b.inclination)]
        out.append("| " + " | ".join(cells) + " |")
    return out


if __name__ == "__main__":
    print("\n".join(rows()))
