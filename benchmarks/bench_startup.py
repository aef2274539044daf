"""Start-up time of ``import andoyer`` and ``andoyer --help`` against Python itself.

Each command runs as a whole process, ``--repeats`` times, the commands interleaved so that
a change in the machine's load touches all of them alike; the table gives the median and the
best wall time and the ratio of medians to ``python -c pass``.

    python3 benchmarks/bench_startup.py --repeats 21
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import time

COMMANDS = {
    "python -c pass": [sys.executable, "-c", "pass"],
    "import andoyer": [sys.executable, "-c", "import andoyer"],
    "andoyer --help": [sys.executable, "-m", "andoyer", "--help"],
    "andoyer bodies": [sys.executable, "-m", "andoyer", "bodies"],
}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=21)
    args = parser.parse_args()
    times: dict[str, list[float]] = {name: [] for name in COMMANDS}
    for _ in range(args.repeats):
        for name, argv in COMMANDS.items():
            start = time.perf_counter()
            subprocess.run(argv, check=True, stdout=subprocess.DEVNULL)
            times[name].append(time.perf_counter() - start)
    base = statistics.median(times["python -c pass"])
    print(f"{'command':<18} {'median (s)':>10} {'best (s)':>9} {'/ python':>9}")
    for name, values in times.items():
        median = statistics.median(values)
        print(f"{name:<18} {median:>10.3f} {min(values):>9.3f} {median / base:>9.2f}")


if __name__ == "__main__":
    main()
