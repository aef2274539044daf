"""Regenerate every reproducible figure and table of the three source papers into one folder.

Runs, in turn, the scripts listed on the documentation's "Reproducing the papers" page, each
writing into ``--out`` (default ``reproduced/``).

Run: ``python3 scripts/reproduce_papers.py --out reproduced`` (a couple of minutes).
"""

from __future__ import annotations

import gurfil_figure1
import gurfil_figure4
import lara_figure1
import lara_table1
import lara_tables_2_5
import pavlov_tables
from _common import output_folder

SCRIPTS = (gurfil_figure1, gurfil_figure4, lara_table1, lara_tables_2_5, lara_figure1, pavlov_tables)


def main(argv: list[str] | None = None) -> None:
    """Run every script with the same ``--out`` folder."""
    out = output_folder(__doc__.splitlines()[0], argv)
    for script in SCRIPTS:
        print(f"== {script.__name__}")
        script.main(["--out", str(out)])


if __name__ == "__main__":
    main()
