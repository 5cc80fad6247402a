"""The calculator page (web/, docs/web.md) in a real headless Chromium, filled as a person
would: held-out form inputs give the CLI's numbers bit for bit, a bad input shows the
CLI's message beside its field and no result, the plot has its points, the deck text is
`viscor dem`'s, and the load and recompute times are measured.

    test_calculator.py BUILD_WEB_DIR VISCOR_CLI

Exit 77 (skipped) without selenium, chromium or chromedriver, unless
VISCOR_REQUIRE_ALL_DEPS=1, where that is a failure.
"""
import json
import math
import os
import pathlib
import shutil
import subprocess
import sys
import time

REQUIRE_ALL = os.environ.get("VISCOR_REQUIRE_ALL_DEPS") == "1"


def missing(what):
    print(f"test_calculator: {what}", file=sys.stderr)
    sys.exit(1 if REQUIRE_ALL else 77)


try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    from selenium.webdriver.support.ui import Select, WebDriverWait
except ImportError:
    missing("no selenium (apt-get install python3-selenium)")

WEB = pathlib.Path(sys.argv[1]).resolve()
CLI = sys.argv[2]
for program in ("chromium", "chromedriver"):
    if not shutil.which(program):
        missing(f"no {program} (apt-get install chromium chromium-driver)")

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)
    return ok


def cli(*args):
    run = subprocess.run([CLI, *args], capture_output=True, text=True)
    return run


def cli_json(*args):
    run = cli(*args, "--json")
    if run.returncode != 0:
        raise RuntimeError(f"viscor {' '.join(args)}: {run.stderr}")
    return json.loads(run.stdout)


def same_double(page_text, cli_value, what):
    """Bit for bit: the page's shortest round-trip decimal and the CLI's number read as doubles."""
    page = float(page_text)
    theirs = float(cli_value)
    return check(page == theirs or (math.isnan(page) and math.isnan(theirs)),
                 f"{what}: page {page_text} != CLI {cli_value}")


# ---- the browser ----

options = webdriver.ChromeOptions()
options.binary_location = shutil.which("chromium")
for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"):
    options.add_argument(flag)
service = Service(executable_path=shutil.which("chromedriver"))
driver = webdriver.Chrome(service=service, options=options)
driver.set_page_load_timeout(30)


def updates():
    return int(driver.find_element(By.TAG_NAME, "body").get_attribute("data-updates") or 0)


def settled(action):
    """Do what a person does, then wait for the page's recompute after it."""
    before = updates()
    action()
    WebDriverWait(driver, 10).until(lambda d: updates() > before)


def type_into(field, text):
    box = driver.find_element(By.ID, field)
    if box.get_attribute("value") == text:
        return
    if box.get_attribute("value"):
        settled(lambda: (box.send_keys(Keys.CONTROL, "a"), box.send_keys(Keys.DELETE)))
    if text:
        settled(lambda: box.send_keys(text))


def choose(select_id, value):
    if driver.find_element(By.ID, select_id).get_attribute("value") == value:
        return
    settled(lambda: Select(driver.find_element(By.ID, select_id)).select_by_value(value))


def radio(name, value):
    button = driver.find_element(By.CSS_SELECTOR, f'input[name="{name}"][value="{value}"]')
    if not button.is_selected():
        settled(button.click)


def value_of(cell):
    return driver.find_element(By.ID, f"out-{cell}").get_attribute("data-value")


def fill(case):
    choose("law", case["law"])
    radio("bead_kind", "mass" if "m" in case else "material")
    choose("partner", case.get("partner", "rigid"))
    radio("ask", "damping" if "target_e" in case else "e")
    for field in ("youngs_modulus", "poisson_ratio", "radius", "density", "m", "k", "wall_youngs_modulus",
                  "wall_poisson_ratio", "other_youngs_modulus", "other_poisson_ratio", "other_radius",
                  "other_density", "v0", "gravity", "force", "target_e", "gamma0", "timestep"):
        if field in case:
            type_into(field, case[field])
        elif field == "timestep":
            type_into(field, "")


def cli_inputs(case):
    """The case as the CLI's physical options."""
    args = ["--model", case["law"]]
    names = {"youngs_modulus": "--youngs-modulus", "poisson_ratio": "--poisson-ratio", "radius": "--radius",
             "density": "--density", "m": "--m", "k": "--k", "wall_youngs_modulus": "--wall-youngs-modulus",
             "wall_poisson_ratio": "--wall-poisson-ratio", "other_youngs_modulus": "--other-youngs-modulus",
             "other_poisson_ratio": "--other-poisson-ratio", "other_radius": "--other-radius",
             "other_density": "--other-density", "v0": "--v0", "gravity": "--gravity", "force": "--force"}
    for field, option in names.items():
        if field in case:
            args += [option, case[field]]
    if case.get("partner") in ("like_bead", "other_bead"):
        args += ["--contact", "pair"]
    return args


def dem_inputs(case):
    args = cli_inputs(case)[2:]
    return [a for a in args]


# Held-out inputs: none of them is a default of the page or a point of the export's tests.
GLASS = {"youngs_modulus": "6.3e10", "poisson_ratio": "0.22", "radius": "1.5e-3", "density": "2480"}
CASES = [
    dict(law="tsuji", **GLASS, v0="0.23", gravity="9.81", force="0", target_e="0.83"),
    dict(law="tsuji", **GLASS, partner="wall_material", wall_youngs_modulus="2.1e11", wall_poisson_ratio="0.29",
         v0="0.07", gravity="9.81", force="1e-4", target_e="0.61"),
    dict(law="hertz_linear_damping", **GLASS, partner="like_bead", v0="0.4", gravity="9.81", force="0",
         target_e="0.9"),
    dict(law="kuwabara_kono", **GLASS, partner="other_bead", other_youngs_modulus="1.9e11",
         other_poisson_ratio="0.3", other_radius="2.5e-3", other_density="7850", v0="0.15", gravity="0",
         force="0", target_e="0.7"),
    dict(law="hunt_crossley", **GLASS, v0="0.05", gravity="0", force="2e-3", target_e="0.45"),
    dict(law="linear", m="3.3e-5", k="1.7e4", v0="0.12", gravity="9.81", force="0", target_e="0.77"),
    dict(law="tsuji", **GLASS, v0="0.31", gravity="9.81", force="0", gamma0="3.1e-8"),
    dict(law="linear", m="3.3e-5", k="1.7e4", v0="0.12", gravity="0", force="0", gamma0="2e-6"),
    # decks for the e the code gets at its time step (about T/50 and T/20 of these impacts)
    dict(law="tsuji", **GLASS, v0="0.23", gravity="9.81", force="0", target_e="0.83", timestep="6.4e-8"),
    dict(law="hertz_linear_damping", **GLASS, partner="wall_material", wall_youngs_modulus="2.1e11",
         wall_poisson_ratio="0.29", v0="0.4", gravity="9.81", force="0", target_e="0.9", timestep="1.5e-7"),
    dict(law="tsuji", **GLASS, partner="other_bead", other_youngs_modulus="1.9e11", other_poisson_ratio="0.3",
         other_radius="2.5e-3", other_density="7850", v0="0.3", gravity="9.81", force="0", target_e="0.75",
         timestep="5e-8"),
    # a stick: a slow bead under a large load
    dict(law="hunt_crossley", **GLASS, v0="0.002", gravity="9.81", force="0.5", gamma0="5e-3"),
]

DEM_MODELS = {"hertz_linear_damping": [("lammps", "velocity"), ("lammps", "mass_velocity")],
              "kuwabara_kono": [("lammps", "viscoelastic")],
              "tsuji": [("lammps", "tsuji"), ("liggghts", "hertz"), ("yade", "mindlin")]}

try:
    url = (WEB / "index.html").as_uri()
    started = time.monotonic()
    driver.get(url)
    WebDriverWait(driver, 10).until(
        lambda d: d.find_element(By.TAG_NAME, "body").get_attribute("data-ready") == "true")
    driver_s = time.monotonic() - started
    # From the navigation's start to the first result shown, as the page measures it.
    ready_ms = float(driver.find_element(By.TAG_NAME, "body").get_attribute("data-ready-ms"))
    print(f"page loaded from file:// and showing its first result {ready_ms:.0f} ms after the navigation started "
          f"({driver_s * 1000:.0f} ms around driver.get)")
    # Again in the running browser, as a person opening the page would find it.
    driver.refresh()
    WebDriverWait(driver, 10).until(
        lambda d: d.find_element(By.TAG_NAME, "body").get_attribute("data-ready") == "true")
    again_ms = float(driver.find_element(By.TAG_NAME, "body").get_attribute("data-ready-ms"))
    print(f"reloaded in the running browser: {again_ms:.0f} ms")
    check(again_ms < 1000, f"the page takes {again_ms:.0f} ms to load in a running browser (wanted < 1 s)")

    # Labels: every input and select has one (what a screen reader announces).
    for element in driver.find_elements(By.CSS_SELECTOR, "input:not([type=radio]), select"):
        labels = driver.find_elements(By.CSS_SELECTOR, f'label[for="{element.get_attribute("id")}"]')
        check(len(labels) == 1, f"field {element.get_attribute('id')} has {len(labels)} labels")

    compute_ms = []
    compared = 0
    for number, case in enumerate(CASES):
        fill(case)
        compute_ms.append(float(driver.find_element(By.TAG_NAME, "body").get_attribute("data-compute-ms")))
        status = driver.find_element(By.ID, "status").text
        where = f"case {number} ({case['law']})"
        if "target_e" in case:
            theirs = cli_json("calibrate", *cli_inputs(case), "--target-e", case["target_e"], "--method", "surrogate")
            check(not status, f"{where}: the page says '{status}'")
            compared += same_double(value_of("gamma0"), theirs["gamma0"], f"{where}: gamma0")
        # e at the page's damping: the surrogate at the page's scaled (gamma, g) is the
        # CLI's `approx --formula surrogate` bit for bit, and the Taylor solve of `cor`
        # (an independent method) within the stated bound.
        scaled = driver.find_element(By.ID, "out-scaled").text
        gamma_text, g_text = (part.split(" = ")[1] for part in scaled.split(", "))
        theirs = cli_json("approx", "--model", case["law"], "--gamma", gamma_text, "--g", g_text, "--formula",
                          "surrogate")
        surrogate_e = theirs["formulas"][0]["e"] if "formulas" in theirs else theirs["e"]
        compared += same_double(value_of("e"), surrogate_e, f"{where}: e")
        gamma0 = value_of("gamma0")
        solved = cli_json("cor", *cli_inputs(case), "--gamma0", gamma0, "--digits", "20")
        outcome = value_of("outcome")
        print(f"{where}: {outcome}, e = {value_of('e')}, gamma0 = {gamma0}")
        check(outcome == solved["outcome"], f"{where}: outcome {outcome}, viscor cor says {solved['outcome']}")
        if outcome == "rebound":
            check(abs(float(value_of("e")) - float(solved["e"])) <= 3e-13,
                  f"{where}: e {value_of('e')} is not within the bound of viscor cor's {solved['e']}")
        for code, model in DEM_MODELS.get(case["law"], []) if "m" not in case else []:
            target = case.get("target_e") or value_of("e")
            if outcome != "rebound" or (code == "yade" and "timestep" not in case):
                continue  # YADE's clamped force: entries at a time step only
            stepped = ["--timestep", case["timestep"]] if "timestep" in case else []
            deck = cli_json("dem", code, "--damping", model, *dem_inputs(case), "--target-e", target, "--method",
                            "surrogate", *stepped)
            section = driver.find_element(By.CSS_SELECTOR, f'section.deck[data-model="{code}-{model}"]')
            page_text = section.find_element(By.TAG_NAME, "pre").text
            # The last line gives the time step; without a step of the user's, the CLI's also
            # gives the contact time, which needs the solve.
            page_lines, cli_lines = page_text.strip().split("\n"), deck["snippet"].strip().split("\n")
            whole = "timestep" in case
            check(page_lines == cli_lines if whole else page_lines[:-1] == cli_lines[:-1],
                  f"{where}: {code} {model} deck text differs:\n{page_text}\n---\n{deck['snippet']}")
            step = lambda line: float(line.split("timestep ")[1].split()[0])
            check(whole or step(page_lines[-1]) == step(cli_lines[-1]),
                  f"{where}: {code} {model} time step: page '{page_lines[-1]}', CLI '{cli_lines[-1]}'")
            compared += 1
            if "builtin_e" in deck:
                shown = section.find_element(By.CSS_SELECTOR, "p.builtin").get_attribute("data-value")
                compared += same_double(shown, deck["builtin_e"], f"{where}: {code} {model} builtin_e")
        # The plot: each curve has points, the mark is the result.
        lines = driver.find_elements(By.CSS_SELECTOR, "#plot polyline")
        check(len(lines) >= 1 and all(int(line.get_attribute("data-count")) >= 20 for line in lines),
              f"{where}: the plot has {[line.get_attribute('data-count') for line in lines]} points per curve")
        if outcome == "rebound":
            mark = driver.find_elements(By.CSS_SELECTOR, "#plot circle.mark")
            check(len(mark) == 1 and mark[0].get_attribute("data-e") == value_of("e"),
                  f"{where}: the plot's mark is not the result")
    check(compared >= 30, f"only {compared} numbers compared")
    print(f"compared {compared} numbers and deck texts with the CLI over {len(CASES)} held-out inputs")
    print(f"recompute per input change: max {max(compute_ms):.1f} ms, median {sorted(compute_ms)[len(compute_ms) // 2]:.1f} ms")
    check(max(compute_ms) < 50, f"a recompute took {max(compute_ms):.1f} ms (wanted < 50 ms)")

    # A bad input: the CLI's message beside the field, no result.
    fill(CASES[0])
    type_into("youngs_modulus", "-6.3e10")
    message = driver.find_element(By.CSS_SELECTOR, 'output.error[for="youngs_modulus"]').text
    run = cli("calibrate", *cli_inputs(dict(CASES[0], youngs_modulus="-6.3e10")), "--target-e", "0.83",
              "--method", "surrogate")
    check(run.returncode == 2 and message and message in run.stderr,
          f"bad input: the page says '{message}', the CLI (exit {run.returncode}) '{run.stderr.strip()}'")
    check(value_of("e") is None and driver.find_element(By.ID, "out-e").text == "",
          "bad input: a result is still shown")
    type_into("youngs_modulus", "6.3e10")
    check(value_of("e") is not None, "the result does not come back once the input is fixed")
    # Gravity pointing away from the wall: the CLI's message with the value as typed.
    type_into("gravity", "-9.81")
    message = driver.find_element(By.CSS_SELECTOR, 'output.error[for="gravity"]').text
    run = cli("calibrate", *cli_inputs(dict(CASES[0], gravity="-9.81")), "--target-e", "0.83", "--method", "surrogate")
    check(run.returncode == 2 and message and message in run.stderr,
          f"negative gravity: the page says '{message}', the CLI (exit {run.returncode}) '{run.stderr.strip()}'")
    check(value_of("e") is None, "negative gravity: a result is still shown")
    type_into("gravity", "9.81")
    # An incomplete form computes nothing.
    type_into("v0", "")
    check(value_of("e") is None and driver.find_element(By.CSS_SELECTOR, 'output.error[for="v0"]').text,
          "an empty impact speed: a result is shown, or no message")
    type_into("v0", CASES[0]["v0"])
    check(value_of("e") is not None, "the result does not come back once v0 is given")

    # Keyboard: the law select and the fields are reachable and usable without a mouse.
    law = driver.find_element(By.ID, "law")
    settled(lambda: law.send_keys(Keys.END))
    check(Select(law).first_selected_option.get_attribute("value") == "hunt_crossley",
          "the law cannot be chosen from the keyboard")

    # The same page from a static server (python3 -m http.server) as from the folder.
    file_e = value_of("e")
    server = subprocess.Popen([sys.executable, "-m", "http.server", "0", "--bind", "127.0.0.1"], cwd=WEB,
                              stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    try:
        line = server.stdout.readline()  # "Serving HTTP on 127.0.0.1 port N (...)"
        port = int(line.split(" port ")[1].split()[0])
        driver.get(f"http://127.0.0.1:{port}/index.html")
        WebDriverWait(driver, 10).until(
            lambda d: d.find_element(By.TAG_NAME, "body").get_attribute("data-ready") == "true")
        fill(dict(CASES[0], law="hunt_crossley"))
        check(value_of("e") == file_e, f"from http.server e = {value_of('e')}, from file:// {file_e}")
    finally:
        server.terminate()
        server.wait()

    size = sum(f.stat().st_size for f in WEB.rglob("*") if f.is_file())
    print(f"web folder: {size / 1e6:.2f} MB")
    check(size < 3e6, f"the web folder is {size / 1e6:.2f} MB (wanted < 3 MB)")
finally:
    driver.quit()

if failures:
    print(f"{len(failures)} failures")
    sys.exit(1)
print("calculator page: all checks passed")
