#!/usr/bin/env python3
"""CPU time per compile and link from the log of tools/time_compile.sh.

Usage: python3 tools/build_time_report.py LOG
Prints every step (user + system seconds, wall seconds) and the sum per target
(the CMakeFiles/<target>.dir part of the output path). docs/performance.md,
"Build time", says how the log is made and what the figures mean.
"""
import re
import sys
from collections import defaultdict


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    steps = []
    with open(sys.argv[1]) as log:
        for line in log:
            fields = line.split(maxsplit=3)
            if len(fields) != 4:  # /usr/bin/time writes "Command exited with non-zero status" lines too
                continue
            try:
                user, system, wall = (float(x) for x in fields[:3])
            except ValueError:
                continue
            steps.append((user + system, wall, fields[3].strip()))
    per_target = defaultdict(float)
    print(f"{'cpu s':>8} {'wall s':>8}  output")
    for cpu, wall, output in sorted(steps, reverse=True):
        match = re.search(r"CMakeFiles/([^/]+)\.dir/", output)
        target = match.group(1) if match else output.rsplit("/", 1)[-1] + " (link)"
        per_target[target] += cpu
        print(f"{cpu:8.1f} {wall:8.1f}  {output}")
    print(f"\n{'cpu s':>8}  target")
    for target, cpu in sorted(per_target.items(), key=lambda kv: -kv[1]):
        print(f"{cpu:8.1f}  {target}")
    print(f"{sum(s[0] for s in steps):8.1f}  total ({len(steps)} steps)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
