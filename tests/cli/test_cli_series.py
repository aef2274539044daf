"""``andoyer series sam``: JSON schema, exact low-order values, formats, files and errors."""

from __future__ import annotations

import json
import re
from fractions import Fraction

import pytest

from andoyer.theories import sam_theory
from andoyer.theories.sam_tables import tables_from_json

RATIONAL = re.compile(r"-?\d+/[1-9]\d*")


@pytest.fixture
def cli(run_cli):
    """``andoyer ARGV`` in process: (exit code, stdout, stderr)."""
    return run_cli


def test_cli_series_sam_json_schema(cli):
    code, out, err = cli("series", "sam", "--order", "5", "--format", "json")
    assert code == 0
    assert err == ""
    doc = json.loads(out)
    assert list(doc) == ["q", "g", "l", "L"]
    for name, family in doc.items():
        assert sorted(family, key=int) == [str(i) for i in range(1, 6)]
        for row in family.values():
            if name == "q":
                assert list(row) == ["0"]
            for m, poly in row.items():
                assert m.isdigit()
                for p, c in poly.items():
                    assert p.isdigit()
                    assert RATIONAL.fullmatch(c)


def test_cli_series_sam_exact_low_orders(cli):
    # Independent values.  Lara §5 prints n_ℓ' = (G/C) α (s − x − (3/4) β² x²/s) for i = 1, i.e.
    # T ⊃ −(G²/2C) α x² β² δ q_1 with q_1 = 1/2.  By hand, the first-order generator of eq. 27 is
    # W₁ = −β L² sin 2ℓ/(4 s G) (ω_ℓ ∂W₁/∂ℓ = H₁ − ⟨H₁⟩, ω_ℓ = α s G/C), so
    # ℓ = ℓ' + ∂W₁/∂L = ℓ' − (β/2) δ sin 2ℓ'  →  ℓ_(1,1) = 1/2,
    # g = g' + ∂W₁/∂G = g' + (β/4) x δ sin 2ℓ'  →  g_(1,1) = 1/4,
    # L = L' − ∂W₁/∂ℓ = L'(1 + (β/2) δ cos 2ℓ')  →  L_(1,1) = 1/2 and no L_(1,0).
    code, out, _ = cli("series", "sam", "--order", "1", "--format", "json")
    assert code == 0
    assert json.loads(out) == {
        "q": {"1": {"0": {"0": "1/2"}}},
        "g": {"1": {"1": {"0": "1/4"}}},
        "l": {"1": {"1": {"0": "1/2"}}},
        "L": {"1": {"1": {"0": "1/2"}}},
    }
    code, out, _ = cli("series", "sam", "--order", "3", "--format", "json")
    doc = json.loads(out)
    assert doc["q"]["2"] == {"0": {"0": "5/8"}}  # the plain-sympy Deprit of test_sam_tables
    assert doc["q"]["3"] == {"0": {"0": "3/4", "2": "9/32"}}


def test_cli_series_sam_json_round_trip_to_fractions(cli):
    code, out, _ = cli("series", "sam", "--order", "6", "--format", "json")
    assert code == 0
    tables = tables_from_json(out)
    theory = sam_theory(7)
    for i in range(1, 7):
        coeffs = theory.q[i]
        assert tables["q"][i][0] == {p: c for p, c in enumerate(coeffs) if c}
        for name in ("g", "l", "L"):
            for (k, m), coeffs in getattr(theory, name).items():
                if k == i:
                    assert tables[name][i][m] == {p: Fraction(c) for p, c in enumerate(coeffs) if c}


def test_cli_series_sam_markdown_and_tex(cli):
    code, out, _ = cli("series", "sam", "--order", "4")
    assert code == 0
    assert "| 4 | 7/8 + 35/32 β² |" in out
    assert "| 4 | 4 | 1/512 |" in out
    code, out, _ = cli("series", "sam", "--order", "4", "--format", "tex")
    assert code == 0
    assert r"4 & $\frac{7}{8} + \frac{35}{32}\beta^{2}$ \\" in out
    assert out.count(r"\begin{tabular}") == 4


def test_cli_series_sam_output_file(cli, tmp_path):
    target = tmp_path / "sam.json"
    code, out, _ = cli("series", "sam", "--order", "2", "--format", "json", "--output", str(target))
    assert code == 0
    assert out == ""
    assert json.loads(target.read_text())["q"]["2"] == {"0": {"0": "5/8"}}
    assert [p.name for p in tmp_path.iterdir()] == ["sam.json"]


@pytest.mark.parametrize(
    ("argv", "match"),
    [
        (["--order", "0"], "order >= 1"),
        (["--order", "-3"], "order >= 1"),
        (["--order", "two"], "order >= 1"),
        (["--order", "2", "--format", "xml"], "invalid choice"),
        ([], "required"),
        (["--order", "2", "--output", "/nonexistent/dir/x.md"], "existing directory"),
    ],
)
def test_cli_series_sam_bad_arguments(cli, argv, match):
    code, out, err = cli("series", "sam", *argv)
    assert code == 2
    assert out == ""
    assert len(err.strip().splitlines()) == 1
    assert match in err
