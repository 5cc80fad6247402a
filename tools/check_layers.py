#!/usr/bin/env python3
"""Checks viscor's header layering (docs/architecture.md).

Every header under include/viscor/<folder>/ may include only headers of its own
folder and of the folders ALLOWED lists for it; nothing but the umbrella and
generated headers may sit directly in include/viscor/. A job's typed API (JOB_API: the
one-shot jobs and jobs/*_result.hpp) never mentions JSON or a text-and-JSON output (JOB_API_FORBIDDEN).
The command-line front end
(src/cli/) holds option parsing and printing only: no threads, signal handling or
file reading and writing of its own (FRONT_END_FORBIDDEN). The Python module
(python/) binds the library's jobs: it includes no header of src/cli/ and calls
no command-line words (PYTHON_FORBIDDEN) outside run_cli, the one documented way
to run the tool itself. Exits 1 and names each
offending include otherwise. Run: python3 tools/check_layers.py [repo root]
"""
import pathlib
import re
import sys

# folder -> the folders it may include besides itself (the layer diagram).
ALLOWED = {
    "core": set(),
    "exact": {"core"},
    "ode": {"core"},
    "impact": {"core", "ode"},
    "certify": {"core", "exact", "ode", "impact"},
    "approx": {"core"},  # never the solvers the approximations are tested against
    "tables": {"core", "exact", "ode", "impact", "certify", "approx"},
    # scenes and surrogate sit side by side and never include each other: evaluate takes a
    # surrogate through core/fast_cor.hpp (docs/architecture.md).
    "scenes": {"core", "exact", "ode", "impact", "certify", "approx", "tables"},
    "surrogate": {"core", "exact", "ode", "impact", "certify", "approx", "tables"},
    "dem": {"core", "exact", "ode", "impact", "certify", "approx", "tables", "scenes", "surrogate"},
    "enclose": {"core"},  # proofs stand alone: never the solvers or closed forms they are checked against
    # the jobs (tables, point batches, scenes, file formats, JSON fields) sit on everything
    "jobs": {"core", "exact", "ode", "impact", "certify", "approx", "tables", "scenes", "surrogate", "dem",
             "enclose"},
    # GoogleTest assertions for outside formulas, on the jobs (target viscor::testing)
    "testing": {"core", "approx", "tables", "scenes", "jobs"},
}
# The front ends parse options and print; the work is the library's (jobs/). These
# words in src/cli/ mean threads, signal handling or a file format written by hand.
FRONT_END_DIRS = ["src/cli"]
FRONT_END_FORBIDDEN = re.compile(
    r"std::thread|std::async|std::mutex|sigaction|std::signal\(|<csignal>|<thread>|std::ifstream|std::ofstream|"
    r"sax_parse|json::parse\(|::open\(|::write\(")
# The Python module sits on the library, not on the command-line tool.
PYTHON_FORBIDDEN = re.compile(r'src/cli|"cli_common\.hpp"|"command_registry\.hpp"|\bcli::|run_cli\(')
PYTHON_RUN_CLI_DEFINITION = re.compile(r"^\s*def run_cli\(")
# Headers that pairs of folders must never include, even where ALLOWED would (the two
# integrators are independent checks of each other, so neither may see the other).
FORBIDDEN_PAIRS = [
    ("ode/taylor_integrator.hpp", "ode/adaptive_integrator.hpp"),
    ("ode/detail/taylor_series.hpp", "ode/adaptive_integrator.hpp"),
    ("impact/detail/taylor_tail.hpp", "ode/adaptive_integrator.hpp"),
    ("impact/taylor_impact.hpp", "impact/adaptive_impact.hpp"),
    ("impact/taylor_impact.hpp", "ode/adaptive_integrator.hpp"),
    ("impact/adaptive_impact.hpp", "ode/taylor_integrator.hpp"),
    ("impact/adaptive_impact.hpp", "impact/detail/impact_systems.hpp"),
    ("impact/adaptive_impact.hpp", "ode/radau_integrator.hpp"),  # the Taylor solver's stiff steps
    ("ode/radau_integrator.hpp", "ode/adaptive_integrator.hpp"),
    ("impact/taylor_impact.hpp", "ode/lobatto_integrator.hpp"),  # the GBS solver's stiff steps
    ("ode/lobatto_integrator.hpp", "ode/radau_integrator.hpp"),
    ("ode/radau_integrator.hpp", "ode/lobatto_integrator.hpp"),
]
# The jobs' typed API: a request in, a result of numbers and types out. Text and JSON
# are made by the render headers (jobs/*_render.hpp), so these never mention them.
# (The formula, scene, table, report and error-map jobs still write JSON themselves.)
JOB_API = re.compile(r"^jobs/((cor|exact|approx|scale|calibrate|dem|bench|speaks_json)_job|\w+_result|precision_used)\.hpp$")
JOB_API_FORBIDDEN = re.compile(r"\bjson\b|command_output|nlohmann")
TOP_LEVEL_OK = {"viscor.hpp", "config.hpp.in"}
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]viscor/([^>"]+)[>"]', re.M)


def main() -> int:
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent.parent)
    base = root / "include" / "viscor"
    problems = []
    for path in sorted(base.iterdir()):
        if path.is_file() and path.name not in TOP_LEVEL_OK:
            problems.append(f"{path.relative_to(root)}: headers belong in a concept folder")
    for path in sorted(base.rglob("*.hpp")):
        rel = path.relative_to(base).as_posix()
        folder = rel.split("/")[0]
        if "/" not in rel:
            continue
        if folder not in ALLOWED:
            problems.append(f"{rel}: folder '{folder}' is not in tools/check_layers.py (add it and its layer)")
            continue
        for target in INCLUDE.findall(path.read_text()):
            tfolder = target.split("/")[0]
            if "/" not in target:  # config.hpp, version.hpp: generated, allowed everywhere
                continue
            if tfolder != folder and tfolder not in ALLOWED[folder]:
                problems.append(f"{rel} includes viscor/{target}: '{folder}' may not depend on '{tfolder}'")
        if JOB_API.match(rel):
            for number, line in enumerate(path.read_text().splitlines(), 1):
                found = JOB_API_FORBIDDEN.search(line)
                if found and not line.lstrip().startswith("//"):
                    problems.append(f"{rel}:{number}: '{found.group(0)}' in a job's typed API: results are numbers "
                                    "and types, rendered in jobs/*_render.hpp")
        for a, b in FORBIDDEN_PAIRS:
            if rel == a and f"viscor/{b}" in path.read_text():
                problems.append(f"{rel} includes viscor/{b}: the two are independent methods")
    for front_end in FRONT_END_DIRS:
        for path in sorted((root / front_end).rglob("*.[ch]pp")):
            for number, line in enumerate(path.read_text().splitlines(), 1):
                if FRONT_END_FORBIDDEN.search(line) and not line.lstrip().startswith("//"):
                    problems.append(f"{path.relative_to(root)}:{number}: '{FRONT_END_FORBIDDEN.search(line).group(0)}' "
                                    "in a front end: threads, signals and file formats belong in include/viscor/jobs/")
    python = root / "python"
    for path in sorted(p for p in python.rglob("*") if p.suffix in (".cpp", ".hpp", ".py", ".txt")) if python.is_dir() else []:
        comment = "//" if path.suffix in (".cpp", ".hpp") else "#"
        for number, line in enumerate(path.read_text().splitlines(), 1):
            found = PYTHON_FORBIDDEN.search(line)
            if found and not PYTHON_RUN_CLI_DEFINITION.match(line) and not line.lstrip().startswith(comment):
                problems.append(f"{path.relative_to(root)}:{number}: '{found.group(0)}' in the Python module: it calls "
                                "the library's jobs (include/viscor/jobs/), not the command-line tool")
    for p in problems:
        print(p)
    print(f"check_layers: {len(problems)} problem(s) in {sum(1 for _ in base.rglob('*.hpp'))} headers")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
