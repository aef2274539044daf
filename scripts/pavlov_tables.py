"""Pavlov's bracket tables (eqs. 1.3–1.6 for e(3), 2.10–2.13 for l(7)), checked entry by entry.

For each algebra the script writes the output of ``andoyer brackets --algebra …`` (every
bracket of the Andoyer–Deprit coordinates, proven with sympy and confirmed at seeded points)
and a table of Pavlov's own entries with three verdicts: the corrected entry computed with the
Lie–Poisson bracket, the corrected entry computed with the canonical bracket of the solution,
and the entry as printed. Only eq. 2.12 ``{l, λ1}`` fails as printed (see the Pavlov errata).

Run: ``python3 scripts/pavlov_tables.py --out reproduced``
(writes ``pavlov_brackets_{so3,e3,l7}.txt`` and ``pavlov_tables.md``; about a minute).
"""

from __future__ import annotations

from _common import output_folder, write

from andoyer.cli import main as andoyer
from andoyer.liepoisson import check_pavlov_table, pavlov_table


def verdict(record: object) -> str:
    """``proven`` (sympy and numbers agree), ``numeric only`` or ``FAILS``."""
    if record.symbolic_ok and record.numeric_ok:
        return "proven"
    return "numeric only" if record.numeric_ok else "FAILS"


def table(algebra: str) -> str:
    """Markdown table of Pavlov's entries for ``algebra`` with the three verdicts."""
    entries = pavlov_table(algebra)
    runs = {
        "lie-poisson": check_pavlov_table(algebra, via="lie-poisson"),
        "canonical": check_pavlov_table(algebra, via="canonical"),
        "printed": check_pavlov_table(algebra, printed=True),
    }
    rows = [
        f"## {algebra}",
        "",
        "| eq. | bracket | right side | Lie–Poisson | canonical | as printed |",
        "| --- | --- | --- | --- | --- | --- |",
    ]
    for k, entry in enumerate(entries):
        for run in runs.values():
            if (run[k].left, run[k].right) != (entry.left, entry.right):
                msg = f"expected the checker's records in table order, got {run[k].left, run[k].right}"
                raise RuntimeError(msg)
        rows.append(
            f"| {entry.equation} | {{{entry.left}, {entry.right}}} | `{entry.rhs}` | "
            + " | ".join(verdict(runs[name][k]) for name in ("lie-poisson", "canonical", "printed"))
            + " |"
        )
    return "\n".join(rows) + "\n"


def main(argv: list[str] | None = None) -> None:
    """Write the ``andoyer brackets`` tables and the checked Pavlov tables."""
    out = output_folder(__doc__.splitlines()[0], argv)
    for algebra in ("so3", "e3", "l7"):
        path = out / f"pavlov_brackets_{algebra}.txt"
        status = andoyer(["brackets", "--algebra", algebra, "--output", str(path)])
        if status:
            raise SystemExit(status)
        print(f"wrote {path}")
    text = "# Pavlov's bracket tables, checked\n\n" + "\n".join(table(a) for a in ("e3", "l7"))
    print(text)
    write(out / "pavlov_tables.md", text)


if __name__ == "__main__":
    main()
