// The calculator page (web/index.html): reads the form, asks the C export through
// WebAssembly (web/viscor_web.c), shows the numbers, the DEM decks and the plot.
// Every number shown comes from the export; this file checks the form (with the
// CLI's messages), formats and draws.
"use strict";

// ---- the export, through viscor_web.c ----

// The DEM models of the export (viscor_dem_model) and the law each calibrates.
const DEM_MODELS = [
  {id: 0, code: "LAMMPS", name: "velocity", law: "hertz_linear_damping"},
  {id: 1, code: "LAMMPS", name: "mass_velocity", law: "hertz_linear_damping"},
  {id: 2, code: "LAMMPS", name: "viscoelastic", law: "kuwabara_kono"},
  {id: 3, code: "LAMMPS", name: "tsuji", law: "tsuji", builtin: "LAMMPS damping tsuji"},
  {id: 4, code: "LIGGGHTS", name: "hertz", law: "tsuji", builtin: "LIGGGHTS model hertz"},
  // YADE clamps the force at zero, which the surrogates do not describe: entries at a time step only
  {id: 5, code: "YADE", name: "mindlin", law: "tsuji", builtin: "YADE Hertz-Mindlin with en (Thornton's fit)", atStepOnly: true},
];

// viscor_deck's doubles in their order (viscor_surrogates.h), after the status.
const DECK_FIELDS = ["damping", "damping_number", "gamma0", "youngs_modulus", "poisson_ratio",
  "wall_youngs_modulus", "wall_poisson_ratio", "other_youngs_modulus", "other_poisson_ratio",
  "cross_youngs_modulus", "bead_bead_youngs_modulus", "bead_bead_damping", "other_other_damping", "builtin_e"];

const OUTCOME = {"-1": "outside the surrogate's domain", 0: "rebound", 1: "stick"};

function wasmApi(module) {
  const buffer = module._malloc(8 * 16);
  const read = (n) => Array.from(module.HEAPF64.subarray(buffer / 8, buffer / 8 + n));
  const law = module.cwrap("viscor_web_law", "number", ["string"]);
  return {
    law,
    setMaterialImpact: module._viscor_web_set_material_impact,
    setBeadImpact: module._viscor_web_set_bead_impact,
    mass: module._viscor_web_mass,
    stiffness: module._viscor_web_stiffness,
    scaledGamma: module._viscor_web_scaled_gamma,
    scaledG: module._viscor_web_scaled_g,
    dampingScale: module._viscor_web_damping_scale,
    dampingFor: module._viscor_web_damping_for,
    criticalGamma: module._viscor_critical_gamma,
    eForEntry: module._viscor_web_e_for_entry,
    cor(s, gamma0) {
      module._viscor_web_cor(s, gamma0, buffer);
      const [outcome, e, oneMinusE, eSquared] = read(4);
      return {outcome, e, oneMinusE, eSquared};
    },
    timeScale: module._viscor_web_time_scale,
    domain(s) {
      module._viscor_web_domain(s, buffer);
      const [gammaMax, gMin, gMax] = read(3);
      return {gammaMax, gMin, gMax};
    },
    bound(s) {
      module._viscor_web_bound(s, buffer);
      const [absE, absESquared, relOneMinusE] = read(3);
      return {absE, absESquared, relOneMinusE};
    },
    deck(model, eTarget, dt) {
      module._viscor_web_deck(model, eTarget, dt, buffer);
      const values = read(1 + DECK_FIELDS.length);
      const deck = {status: values[0]};
      DECK_FIELDS.forEach((name, i) => { deck[name] = values[i + 1]; });
      return deck;
    },
  };
}

// ---- numbers as text ----

// The shortest decimal that reads back as the same double, written as C++'s
// std::to_chars writes it (the CLI's deck numbers): fixed or scientific, whichever
// is shorter, fixed on a tie; the exponent with a sign and at least two digits.
function deckNumber(x) {
  if (x === 0) return Object.is(x, -0) ? "-0" : "0";
  const [mantissa, exponentText] = x.toExponential().split("e");
  const exponent = Number(exponentText);
  const sign = mantissa.startsWith("-") ? "-" : "";
  const digits = mantissa.replace("-", "").replace(".", "");
  const expAbs = Math.abs(exponent);
  const scientific = sign + digits[0] + (digits.length > 1 ? "." + digits.slice(1) : "") + "e" +
      (exponent < 0 ? "-" : "+") + (expAbs < 10 ? "0" : "") + expAbs;
  let fixed;
  if (exponent >= digits.length - 1) fixed = sign + digits + "0".repeat(exponent - digits.length + 1);
  else if (exponent >= 0) fixed = sign + digits.slice(0, exponent + 1) + "." + digits.slice(exponent + 1);
  else fixed = sign + "0." + "0".repeat(-exponent - 1) + digits;
  return fixed.length <= scientific.length ? fixed : scientific;
}

// A result for people: 17 significant digits are the double (the bound says how many are right).
const shown = (x) => (Number.isFinite(x) ? deckNumber(x) : "none");

// ---- the form ----

const FIELDS = ["youngs_modulus", "poisson_ratio", "radius", "density", "m", "k", "wall_youngs_modulus",
  "wall_poisson_ratio", "other_youngs_modulus", "other_poisson_ratio", "other_radius", "other_density",
  "v0", "gravity", "force", "target_e", "gamma0", "timestep"];

function choice(name) {
  const checked = document.querySelector(`input[name="${name}"]:checked`);
  return checked ? checked.value : document.getElementById(name).value;
}

// Whether a field is part of the form as it stands (its group is shown).
function active(id) {
  const group = document.getElementById(id).closest("[data-when]");
  return !group || !group.hidden;
}

function showGroups() {
  for (const group of document.querySelectorAll("[data-when]")) {
    const [name, value] = group.dataset.when.split("=");
    group.hidden = choice(name) !== value;
  }
}

// A number as the CLI reads one: a decimal (with an exponent), nothing else.
const DECIMAL = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;

// A double as the CLI's messages write it (to_decimal_string: 17 significant digits).
function cliNumber(x) {
  const [mantissa, exponent] = x.toExponential(16).split("e");
  const sign = exponent[0];
  const digits = exponent.slice(1);
  return `${mantissa}e${sign}${digits.length < 2 ? "0" + digits : digits}`;
}

// The CLI's checks of each input, with its messages (viscor calibrate and viscor cor;
// tests/web/test_calculator.py compares them with the CLI's). The text as typed is
// quoted where the CLI quotes it.
const positive = (name) => (x) => (x > 0 ? null : `parameter ${name} must be > 0, got ${cliNumber(x)}`);
const poisson = (name) => (x) => (x > -1 && x <= 0.5 ? null : `parameter ${name} must be in (-1, 0.5], got ${cliNumber(x)}`);
const RULES = {
  youngs_modulus: positive("bead.youngs_modulus"),
  poisson_ratio: poisson("bead.poisson_ratio"),
  radius: positive("radius"),
  density: positive("density"),
  m: positive("m"),
  k: positive("k"),
  wall_youngs_modulus: positive("wall.youngs_modulus"),
  wall_poisson_ratio: poisson("wall.poisson_ratio"),
  other_youngs_modulus: positive("other_youngs_modulus"),
  other_poisson_ratio: poisson("other_poisson_ratio"),
  other_radius: positive("other_radius"),
  other_density: positive("other_density"),
  v0: positive("v0"),
  gravity: (x, text) => (x >= 0 ? null : `gravity ${text} is negative: gravity is the acceleration towards the wall, ` +
      "counted positive (a bead dropped on a floor under Earth's gravity: 9.81, not -9.81); a load that pulls the " +
      "bead away from the wall is a negative force"),
  force: () => null,
  timestep: positive("timestep"),
  target_e: (x, text) => (x >= 0.01 && x < 1 ? null : `target_e must be in [0.01, 1), got ${text}`),
  gamma0: (x) => (x >= 0 ? null : `parameter gamma0 must be >= 0, got ${cliNumber(x)}`),
};

// Fields that may stay empty: the DEM time step (empty: the continuous impact).
const OPTIONAL = new Set(["timestep"]);

// The form's values, or null with each offending field's message shown beside it.
function readForm() {
  const values = {text: {}};
  let complete = true;
  for (const id of FIELDS) {
    const input = document.getElementById(id);
    const message = document.querySelector(`output.error[for="${id}"]`);
    let error = null;
    if (active(id) && !(OPTIONAL.has(id) && input.value.trim() === "")) {
      const text = input.value.trim();
      if (text === "") error = `${id} is missing`;
      else if (!DECIMAL.test(text) || !Number.isFinite(Number(text)))
        error = `parameter ${id} must be a finite decimal number, but got '${text}'`;
      else {
        const x = Number(text);
        error = RULES[id](x, text);
        values[id] = x;
        values.text[id] = text;
      }
    }
    message.textContent = error || "";
    input.setAttribute("aria-invalid", error ? "true" : "false");
    if (error) complete = false;
  }
  if (!complete) return null;
  values.law = choice("law");
  values.bead_kind = choice("bead_kind");
  values.partner = choice("partner");
  values.ask = choice("ask");
  return values;
}

const PARTNERS = {rigid: 0, wall_material: 1, like_bead: 2, other_bead: 3};

// Sets the export's impact at speed v0 and load (gravity, force); false if it refuses it.
function setImpact(api, f, v0, gravity, force) {
  if (f.bead_kind === "mass") {
    api.setBeadImpact(f.m, f.k, v0, gravity, force);
    return true;
  }
  const nan = NaN;
  const wall = f.partner === "wall_material";
  const other = f.partner === "other_bead";
  return api.setMaterialImpact(f.youngs_modulus, f.poisson_ratio, f.radius, f.density, PARTNERS[f.partner],
      wall ? f.wall_youngs_modulus : nan, wall ? f.wall_poisson_ratio : nan,
      other ? f.other_youngs_modulus : nan, other ? f.other_poisson_ratio : nan,
      other ? f.other_radius : nan, other ? f.other_density : nan, v0, gravity, force) === 1;
}

// ---- one computation ----

function compute(api, f) {
  const s = api.law(f.law);
  if (f.bead_kind === "material" && f.law === "linear")
    return {error: "youngs_modulus gives a Hertz stiffness, which holds only for alpha = 3/2; the law has alpha = 1: " +
      "give k instead"};
  if (f.bead_kind === "mass" && f.partner !== "rigid")
    return {error: "a wall of a material or a second bead needs the bead's material (youngs_modulus, ...)"};
  if (!setImpact(api, f, f.v0, f.gravity, f.force)) return {error: "the export refuses these inputs (a value out of range)"};
  const r = {law: f.law, mass: api.mass(), stiffness: api.stiffness(), bound: api.bound(s)};
  r.gamma0 = f.ask === "damping" ? api.dampingFor(s, f.target_e) : f.gamma0;
  if (!Number.isFinite(r.gamma0)) {
    r.error = `no damping in the surrogate's domain gives e = ${f.target_e} at this impact`;
    return r;
  }
  Object.assign(r, api.cor(s, r.gamma0));
  r.gamma = api.scaledGamma(s, r.gamma0);
  r.g = api.scaledG(s);
  if (r.outcome === -1) {
    const d = api.domain(s);
    r.error = `gamma = ${shown(r.gamma)}, g = ${shown(r.g)} is outside the domain of the ${f.law} surrogate ` +
        `(0 <= gamma <= ${shown(d.gammaMax)}, ${shown(d.gMin)} <= g <= ${shown(d.gMax)})`;
  }
  r.timeScale = api.timeScale(s);
  r.criticalGamma0 = api.criticalGamma(s, r.g) / api.dampingScale(s);
  r.targetE = f.ask === "damping" ? f.target_e : r.e;
  r.decks = [];
  if (f.bead_kind === "material" && r.targetE >= 0.01 && r.targetE < 1)
    for (const model of DEM_MODELS.filter((m) => m.law === f.law && (!m.atStepOnly || f.timestep))) {
      const dt = f.timestep ?? 0;
      const deck = api.deck(model.id, r.targetE, dt);
      r.decks.push({model, deck, text: deck.status === 0 ? snippet(model, f, deck) + timeStepLine(model, r.timeScale, dt) : null});
    }
  r.curves = curves(api, s, f, r);
  return r;
}

// ---- the plot's values ----

const PLOT_POINTS = 61;

// e(v0) at the damping found, with the load and without, and each code's built-in
// conversion of the target e, on a log grid from v0/30 to 30 v0.
function curves(api, s, f, r) {
  const speeds = Array.from({length: PLOT_POINTS}, (_, i) => f.v0 * Math.pow(900, i / (PLOT_POINTS - 1)) / 30);
  const series = [];
  const along = (label, at) => {
    const points = [];
    for (const v of speeds) {
      const e = at(v);
      if (Number.isFinite(e)) points.push([v, e]);
    }
    series.push({label, points});
  };
  along("with the load", (v) => (setImpact(api, f, v, f.gravity, f.force) ? api.cor(s, r.gamma0).e : NaN));
  if (f.gravity !== 0 || f.force !== 0)
    along("without load", (v) => (setImpact(api, f, v, 0, 0) ? api.cor(s, r.gamma0).e : NaN));
  if (f.bead_kind === "material")
    for (const model of DEM_MODELS.filter((m) => m.builtin && !m.atStepOnly && m.law === f.law))
      along(`${model.builtin}'s own conversion of e = ${shown(r.targetE)}`,
          (v) => (setImpact(api, f, v, f.gravity, f.force) ? api.eForEntry(model.id, r.targetE) : NaN));
  setImpact(api, f, f.v0, f.gravity, f.force);
  return series;
}

// ---- the decks (the CLI's snippets: include/viscor/dem/deck_snippet.hpp) ----

const BEAD_BEAD_COMMENT =
    "# like beads: calibrated for two such beads at the same e and approach speed, without load (viscor calibrates\n" +
    "# the contact you measured; if like beads rebound differently, run viscor dem --contact pair with their e)\n";

// The deck's last line: the step the entries were calibrated for, or the drop decks' step,
// T/400 of the time scale T (include/viscor/dem/drop_deck.hpp); for the latter the CLI's
// line also gives the contact time, which needs the solve: not here.
const STEPS_PER_TIME_SCALE = 400;
function timeStepLine(model, timeScale, dt) {
  if (dt > 0 && model.code === "YADE") return `O.dt = ${cliNumber(dt)}  # exactly: the entries are calibrated for this step\n`;
  if (dt > 0) return `# time step: timestep ${cliNumber(dt)} exactly: the entries are calibrated for this step\n`;
  const step = timeScale / STEPS_PER_TIME_SCALE;
  return `# time step: timestep ${deckNumber(Number(step.toPrecision(6)))} or smaller ` +
         `(T/${STEPS_PER_TIME_SCALE} of the time scale T = ${shown(timeScale)} s)\n`;
}

function snippet(model, f, deck) {
  const n = (x) => (Number.isFinite(x) ? deckNumber(x) : null);
  const d = {};
  for (const name of DECK_FIELDS) d[name] = n(deck[name]);
  const wall = f.partner === "rigid" || f.partner === "wall_material";
  // LIGGGHTS's rigid wall type: the CLI writes the modulus as its convention spells it.
  if (f.partner === "rigid" && deck.wall_youngs_modulus === 1e30) d.wall_youngs_modulus = "1e30";
  if (model.code === "YADE") return yadeSnippet(f, wall, d);
  return model.code === "LAMMPS" ? lammpsSnippet(model, wall, f.partner === "wall_material", d)
                                 : liggghtsSnippet(wall, d);
}

// YADE's script names the beads' sizes, densities, speed and load: the form's texts, as the
// CLI writes the request's.
function yadeSnippet(f, wall, d) {
  const wallMaterial = f.partner === "wall_material";
  const other = f.partner === "other_bead";
  let s = "# YADE 2023.02a, Hertz-Mindlin with viscous damping betan (the total normal force is clamped at 0)\n";
  s += `bead = O.materials.append(FrictMat(young=${d.youngs_modulus}, poisson=${d.poisson_ratio}, density=DENSITY, frictionAngle=0))\n`;
  if (wall) {
    s += wallMaterial
        ? "# a wall of its own material; YADE takes R* = R/2 on a wall, hence young = sqrt(2) E for bead and\n" +
          "# wall: bead-wall only, two beads of these would be too stiff (for bead-bead run viscor dem --contact pair)\n"
        : "# rigid wall; YADE takes R* = R/2 on a wall, hence the bead's young = sqrt(2) E: bead-wall only,\n" +
          "# two beads of this material would be too stiff (for bead-bead run viscor dem --contact pair)\n";
    s += `${wallMaterial ? "plate" : "rigid"} = O.materials.append(FrictMat(young=${d.wall_youngs_modulus ?? d.youngs_modulus}, ` +
         `poisson=${d.wall_poisson_ratio ?? d.poisson_ratio}, density=DENSITY, frictionAngle=0))\n`;
  } else if (other) {
    s += `other = O.materials.append(FrictMat(young=${d.other_youngs_modulus}, poisson=${d.other_poisson_ratio ?? d.poisson_ratio}, ` +
         "density=OTHER_DENSITY, frictionAngle=0))\n";
  }
  if (wall) {
    s += `O.bodies.append([utils.wall(0, axis=2, material=${wallMaterial ? "plate" : "rigid"}), ` +
         "utils.sphere((0, 0, RADIUS), RADIUS, material=bead)])\n";
    s += "O.bodies[1].state.vel = (0, 0, -V0)  # the impact speed\n";
  } else {
    s += other ? "O.bodies.append([utils.sphere((0, 0, 0), RADIUS, material=bead), " +
                 "utils.sphere((0, 0, RADIUS + OTHER_RADIUS), OTHER_RADIUS, material=other)])\n"
               : "O.bodies.append([utils.sphere((0, 0, 0), RADIUS, material=bead), " +
                 "utils.sphere((0, 0, 2 * RADIUS), RADIUS, material=bead)])\n";
    s += "O.bodies[0].state.vel, O.bodies[1].state.vel = (0, 0, V0 / 2), (0, 0, -V0 / 2)  # approaching at V0\n";
  }
  s += `O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()${wall ? ", Bo1_Wall_Aabb()" : ""}]),\n`;
  s += `    InteractionLoop([${wall ? "Ig2_Wall_Sphere_ScGeom()" : "Ig2_Sphere_Sphere_ScGeom()"}], ` +
       `[Ip2_FrictMat_FrictMat_MindlinPhys(betan=${d.damping})], [Law2_ScGeom_MindlinPhys_Mindlin()]),\n`;
  s += "    NewtonIntegrator(damping=0, gravity=(0, 0, -GRAVITY))]\n";
  const names = {OTHER_DENSITY: f.text.other_density, OTHER_RADIUS: f.text.other_radius, DENSITY: f.text.density,
    RADIUS: f.text.radius, GRAVITY: f.text.gravity, V0: f.text.v0};
  for (const [name, value] of Object.entries(names)) s = s.split(name).join(value ?? "");
  return s;
}

function lammpsSnippet(model, wall, wallMaterial, d) {
  const tail = ` damping ${model.name} tangential linear_nohistory 0 0`;
  const entry = (E, damping, nu) => `hertz/material ${E} ${damping} ${nu}${tail}`;
  let s = "# tangential linear_nohistory 0 0: frictionless; put your own (a head-on impact does not feel it)\n";
  if (wall) {
    s += wallMaterial ? "# bead-wall: a plane z = 0 of its own material; LAMMPS' wall has no material and reads " +
                            "E_deck/(2(1-nu)): E_deck = 2(1-nu) E*, E* of bead and wall\n"
                      : "# bead-wall: a rigid plane z = 0 (LAMMPS' wall reads E_deck/(2(1-nu)): E_deck = 2E/(1+nu))\n";
    s += `fix wall all wall/gran granular ${entry(d.youngs_modulus, d.damping, d.poisson_ratio)} zplane 0.0 NULL\n`;
    if (d.bead_bead_damping !== null) {
      s += BEAD_BEAD_COMMENT + "pair_style granular\n";
      s += `pair_coeff * * ${entry(d.bead_bead_youngs_modulus ?? d.youngs_modulus, d.bead_bead_damping, d.poisson_ratio)}\n`;
    }
    return s;
  }
  s += "pair_style granular\n";
  if (d.other_youngs_modulus === null) return s + `pair_coeff * * ${entry(d.youngs_modulus, d.damping, d.poisson_ratio)}\n`;
  s += "# type 1: the bead, type 2: the other bead. (1,2) is the contact calibrated; LAMMPS 29 Sep 2021 mixes\n" +
       "# hertz/material entries wrongly, so it is explicit: E_deck = 2(1-nu^2) E*, E* of the two materials\n";
  s += `pair_coeff 1 2 ${entry(d.cross_youngs_modulus ?? d.youngs_modulus, d.damping, d.poisson_ratio)}\n`;
  s += BEAD_BEAD_COMMENT;
  s += `pair_coeff 1 1 ${entry(d.youngs_modulus, d.bead_bead_damping ?? d.damping, d.poisson_ratio)}\n`;
  s += `pair_coeff 2 2 ${entry(d.other_youngs_modulus, d.other_other_damping ?? d.damping,
      d.other_poisson_ratio ?? d.poisson_ratio)}\n`;
  return s;
}

function liggghtsSnippet(wall, d) {
  const type2Modulus = (wall ? d.wall_youngs_modulus : d.other_youngs_modulus) ?? d.youngs_modulus;
  const type2Nu = (wall ? d.wall_poisson_ratio : d.other_poisson_ratio) ?? d.poisson_ratio;
  let s = "hard_particles yes  # allows youngsModulus > 1e9 Pa in SI units\n";
  s += (wall ? "# type 1: the bead, type 2: the wall" : "# type 1: the bead, type 2: the other bead") +
       " (LIGGGHTS combines the two types' Y and nu)\n";
  s += `fix m1 all property/global youngsModulus peratomtype ${d.youngs_modulus} ${type2Modulus}\n`;
  s += `fix m2 all property/global poissonsRatio peratomtype ${d.poisson_ratio} ${type2Nu}\n`;
  const e = d.damping;
  const e11 = d.bead_bead_damping ?? e;
  const e22 = wall ? e : d.other_other_damping ?? e;
  if (wall || d.bead_bead_damping !== null) {
    s += `# coefficientRestitution (i,j): (1,1) bead-bead = ${e11}, (1,2) = (2,1) ` +
         `${wall ? "bead-wall" : "bead-other bead"} = ${e}, (2,2) ${wall ? "unused" : "= " + e22}\n`;
    s += BEAD_BEAD_COMMENT;
  }
  s += `fix m3 all property/global coefficientRestitution peratomtypepair 2 ${e11} ${e} ${e} ${e22}\n`;
  s += "# tangential history needs coefficientFriction: frictionless here; put your own (a head-on impact does not feel it)\n";
  s += "fix m4 all property/global coefficientFriction peratomtypepair 2 0 0 0 0\n";
  s += "pair_style gran model hertz tangential history\npair_coeff * *\n";
  if (wall) s += "fix wall all wall/gran model hertz tangential history primitive type 2 zplane 0.0\n";
  return s;
}

// ---- showing it ----

function setValue(id, text, value) {
  const cell = document.getElementById(id);
  cell.textContent = text;
  if (value === undefined) delete cell.dataset.value;
  else cell.dataset.value = Number.isFinite(value) ? deckNumber(value) : String(value);
}

function clearResults(message) {
  document.getElementById("status").textContent = message;
  for (const cell of document.querySelectorAll("#numbers dd")) setValue(cell.id, "");
  document.getElementById("decks").replaceChildren();
  document.getElementById("deck-note").textContent = "";
  drawPlot([], null);
}

function showResult(f, r) {
  document.getElementById("status").textContent = r.error || "";
  if (r.error && r.e === undefined) {
    for (const cell of document.querySelectorAll("#numbers dd")) setValue(cell.id, "");
    document.getElementById("decks").replaceChildren();
    drawPlot([], null);
    return;
  }
  setValue("out-e", shown(r.e), r.e);
  setValue("out-one_minus_e", shown(r.oneMinusE), r.oneMinusE);
  setValue("out-outcome", OUTCOME[r.outcome], OUTCOME[r.outcome]);
  setValue("out-gamma0", shown(r.gamma0), r.gamma0);
  setValue("out-critical_gamma0", Number.isFinite(r.criticalGamma0) ? shown(r.criticalGamma0) : "never (no sticking in the domain)",
      r.criticalGamma0);
  setValue("out-bound", `|e_s - e| <= ${shown(r.bound.absE)} (where e >= 0.01), |e_s^2 - e^2| <= ${shown(r.bound.absESquared)}`);
  setValue("out-contact", `m* = ${shown(r.mass)} kg, k = ${shown(r.stiffness)}`);
  setValue("out-scaled", `gamma = ${shown(r.gamma)}, g = ${shown(r.g)}`);
  showDecks(f, r);
  drawPlot(r.curves, [f.v0, r.e]);
}

function showDecks(f, r) {
  const box = document.getElementById("decks");
  box.replaceChildren();
  const note = document.getElementById("deck-note");
  if (f.bead_kind !== "material") note.textContent = "DEM codes take the bead's material: give it to see their entries.";
  else if (!(r.targetE >= 0.01 && r.targetE < 1))
    note.textContent = `No deck: the codes' entries are calibrated for 0.01 <= e < 1, and e = ${shown(r.targetE)}.`;
  else if (r.decks.length === 0)
    note.textContent = `No code of this export calibrates the ${f.law} law (LAMMPS velocity, mass_velocity: ` +
        "hertz_linear_damping; viscoelastic: kuwabara_kono; LAMMPS tsuji and LIGGGHTS hertz: tsuji). " +
        "YADE's laws clamp the force at zero: run viscor dem yade for them.";
  else note.textContent = (f.law === "tsuji" && !f.timestep ? "YADE's Hertz-Mindlin clamps the force at zero: " +
      "give a time step for its entries. " : "") + `The entries that give e = ${shown(r.targetE)} at this impact, ready to copy` +
      (f.timestep ? `, when the code steps it with dt = ${shown(f.timestep)} s (T/${(r.timeScale / f.timestep).toFixed(1)} of the time scale T).`
                  : ", for the continuous impact (give a time step for the e the code gets at its step).");
  for (const {model, deck, text} of r.decks) {
    const section = document.createElement("section");
    section.className = "deck";
    section.dataset.model = `${model.code.toLowerCase()}-${model.name}`;
    const title = document.createElement("h3");
    title.textContent = `${model.code} ${model.name}`;
    section.append(title);
    if (text === null) {
      const p = document.createElement("p");
      p.textContent = "No entry of this model gives this e at this impact.";
      section.append(p);
    } else {
      const pre = document.createElement("pre");
      pre.textContent = text;
      pre.tabIndex = 0;
      pre.setAttribute("aria-label", `${model.code} ${model.name} input lines`);
      section.append(pre);
      const copy = document.createElement("button");
      copy.type = "button";
      copy.textContent = "Copy";
      copy.addEventListener("click", () => navigator.clipboard && navigator.clipboard.writeText(text));
      section.append(copy);
      if (Number.isFinite(deck.builtin_e)) {
        const p = document.createElement("p");
        p.className = "builtin";
        p.dataset.value = deckNumber(deck.builtin_e);
        p.textContent = `The code's own conversion (${model.builtin}) of e = ${shown(r.targetE)} would give ` +
            `e = ${shown(deck.builtin_e)} at this impact${model.atStepOnly ? " and step" : ""}.`;
        section.append(p);
      }
    }
    box.append(section);
  }
}

// ---- the plot (SVG, log v0) ----

const SVG = "http://www.w3.org/2000/svg";
const COLOURS = ["#1b6ca8", "#7a7a7a", "#c2452d", "#8a5a00"];

function svg(name, attributes, text) {
  const node = document.createElementNS(SVG, name);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, value);
  if (text !== undefined) node.textContent = text;
  return node;
}

function drawPlot(series, mark) {
  const plot = document.getElementById("plot");
  plot.replaceChildren();
  const all = series.flatMap((c) => c.points);
  if (all.length === 0) return;
  const box = {left: 60, right: 620, top: 20, bottom: 300};
  const vs = all.map((p) => Math.log10(p[0]));
  const es = all.map((p) => p[1]).concat(mark && Number.isFinite(mark[1]) ? [mark[1]] : []);
  const [v0, v1] = [Math.min(...vs), Math.max(...vs)];
  let [e0, e1] = [Math.min(...es), Math.max(...es)];
  if (e1 - e0 < 1e-9) [e0, e1] = [e0 - 0.01, e1 + 0.01];
  const x = (v) => box.left + (box.right - box.left) * (Math.log10(v) - v0) / (v1 - v0 || 1);
  const y = (e) => box.bottom - (box.bottom - box.top) * (e - e0) / (e1 - e0);
  plot.append(svg("rect", {x: box.left, y: box.top, width: box.right - box.left, height: box.bottom - box.top,
    class: "frame"}));
  for (let p = Math.ceil(v0); p <= Math.floor(v1); ++p)
    plot.append(svg("text", {x: x(10 ** p), y: box.bottom + 18, "text-anchor": "middle"}, `1e${p}`));
  for (const e of [e0, (e0 + e1) / 2, e1])
    plot.append(svg("text", {x: box.left - 6, y: y(e) + 4, "text-anchor": "end"}, e.toFixed(4)));
  plot.append(svg("text", {x: (box.left + box.right) / 2, y: 340, "text-anchor": "middle"}, "impact speed v0 (m/s)"));
  plot.append(svg("text", {x: box.left - 6, y: box.top - 6, "text-anchor": "end"}, "e"));
  series.forEach((c, i) => {
    const colour = COLOURS[i % COLOURS.length];
    plot.append(svg("polyline", {points: c.points.map(([v, e]) => `${x(v)},${y(e)}`).join(" "), stroke: colour,
      fill: "none", "stroke-width": 2, "data-series": c.label, "data-count": c.points.length,
      "data-values": c.points.map(([v, e]) => `${deckNumber(v)}:${deckNumber(e)}`).join(" ")}));
    plot.append(svg("line", {x1: box.left, x2: box.left + 24, y1: 366 + 16 * i, y2: 366 + 16 * i, stroke: colour,
      "stroke-width": 2}));
    plot.append(svg("text", {x: box.left + 32, y: 370 + 16 * i}, c.label));
  });
  if (mark && Number.isFinite(mark[1]))
    plot.append(svg("circle", {cx: x(mark[0]), cy: y(mark[1]), r: 6, class: "mark", "data-v0": deckNumber(mark[0]),
      "data-e": deckNumber(mark[1])}));
}

// ---- wiring ----

function start(module) {
  const api = wasmApi(module);
  const form = document.getElementById("form");
  const update = () => {
    const started = performance.now();
    showGroups();
    const f = readForm();
    if (f === null) clearResults("Fix the marked fields: nothing is computed from an incomplete form.");
    else {
      const r = compute(api, f);
      showResult(f, r);
    }
    document.body.dataset.computeMs = String(performance.now() - started);
    document.body.dataset.updates = String(Number(document.body.dataset.updates || 0) + 1);
  };
  form.addEventListener("input", update);
  form.addEventListener("change", update);
  update();
  document.body.dataset.readyMs = String(performance.now());  // since the navigation started
  document.body.dataset.ready = "true";
}

ViscorModule().then(start);
