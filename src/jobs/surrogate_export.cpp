// The C export of the committed surrogates (jobs/surrogate_export.hpp): the C text
// and the files it is written to.
#include <viscor/jobs/surrogate_export.hpp>

#include <viscor/core/exceptions.hpp>
#include <viscor/jobs/dem_export.hpp>
#include <viscor/jobs/files.hpp>
#include <viscor/core/sha256.hpp>
#include <viscor/jobs/surrogate_files.hpp>
#include <viscor/surrogate/cor_surrogate.hpp>
#include <viscor/surrogate/surrogate_verify.hpp>
#include <viscor/tables/reference_table.hpp>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace viscor::jobs {

namespace detail {

// A double as a C literal that reads back exactly (17 significant digits, and a
// decimal point so that it is a floating literal even where it is an integer).
std::string c_double(double x) {
  std::string s = surrogate::exact_text(x);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string c_doubles(const std::vector<double>& v, std::size_t per_line, const std::string& indent) {
  std::string out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i % per_line == 0) out += indent;
    out += c_double(v[i]);
    if (i + 1 < v.size()) out += ',';
    out += (i + 1) % per_line == 0 || i + 1 == v.size() ? "\n" : " ";
  }
  return out;
}

// The laws to export, in the order of viscor::named_laws.
std::vector<std::string> export_law_names(const surrogate_export_options& o) {
  std::vector<std::string> names;
  const bool all = o.laws.empty() || (o.laws.size() == 1 && o.laws[0] == "all");
  if (all) {
    for (const auto& n : named_laws)
      if (std::filesystem::exists(o.surrogate_directory + "/" + std::string(n.name) + ".surrogate"))
        names.emplace_back(n.name);
    if (names.empty())
      throw invalid_parameter("surrogate export: no committed surrogate in '" + o.surrogate_directory + "'");
    return names;
  }
  for (const auto& law : o.laws) {
    (void)law_by_name(law);  // throws invalid_parameter listing the valid names
    if (!std::filesystem::exists(o.surrogate_directory + "/" + law + ".surrogate"))
      throw invalid_parameter("surrogate export: no committed surrogate for law '" + law + "' in '" +
                              o.surrogate_directory + "'");
    names.push_back(law);
  }
  return names;
}

std::string c_comment_number(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2e", x);
  return b;
}

struct law_export {
  std::string name;
  surrogate::cor_surrogate s;
  std::string surrogate_sha256, verification_sha256;
  std::vector<surrogate::region_errors> regions;
};

// The export states the surrogate's bound and prints its measured maxima beside it:
// refused when the bound is missing, when the table judged nothing, or when a maximum
// over all the verification points exceeds the bound (or an outcome is wrong).
void refuse_a_bound_its_table_breaks(const law_export& l, const std::string& path) {
  const surrogate::surrogate_bound& b = l.s.bound;
  if (!b.verified())
    throw invalid_parameter("surrogate export: " + path + " states no verified bound (never verified): "
                            "verify it (viscor surrogate build) before exporting it");
  const surrogate::region_errors& all = l.regions.at(0);  // region_names[0]: every point
  const std::size_t judged = all.points - all.outside_domain - all.exempt - all.left_out;
  std::string broken;
  const auto note = [&](const std::string& what) { broken += (broken.empty() ? "" : "; ") + what; };
  const auto check = [&](const char* what, double measured, double bound) {
    if (!(measured <= bound)) note(std::string(what) + " " + c_comment_number(measured) + " > bound " + c_comment_number(bound));
  };
  check("max|de|", all.abs_e, b.abs_e);
  check("max|de^2|", all.abs_e_squared, b.abs_e_squared);
  check("rel d(1-e)", all.rel_one_minus_e, b.rel_one_minus_e);
  if (all.wrong_outcomes > 0) note(std::to_string(all.wrong_outcomes) + " wrong outcomes");
  if (judged == 0) note("no verification point judged");
  if (!broken.empty())
    throw invalid_parameter("surrogate export: " + path + " breaks the bound it states on its own verification table (" +
                            path + ".verification.csv): " + broken + "; refusing to export it");
}

// A law's surrogate and its verification table, each read once and checked against the
// manifest beside it (a file changed after viscor wrote it is refused), and the accuracy
// the surrogate has on that table: an export never states a bound its own table breaks.
law_export read_law_export(const std::string& directory, const std::string& name) {
  law_export l;
  l.name = name;
  const std::string path = directory + "/" + name + ".surrogate";
  const std::string body = read_checked_file<invalid_parameter>(path, "surrogate file");
  std::istringstream in(body);
  l.s = surrogate::read_cor_surrogate(in, path);
  l.surrogate_sha256 = sha256_hex(body);
  const std::string table = path + ".verification.csv";
  const std::string rows = read_checked_file<invalid_parameter>(table, "verification table");
  l.verification_sha256 = sha256_hex(rows);
  l.regions = surrogate::compare_with_reference(l.s, verification_rows(parse_table(rows, table), table),
                                                surrogate::surrogate_targets{}, 25);
  refuse_a_bound_its_table_breaks(l, path);
  return l;
}

std::string tree_data(const std::string& prefix, const surrogate::patch_tree& t) {
  std::ostringstream o;
  o << "static const viscor_sg_node " << prefix << "_nodes[" << t.nodes.size() << "] = {\n";
  for (std::size_t i = 0; i < t.nodes.size(); ++i)
    o << "    {" << c_double(t.nodes[i].split) << ", " << t.nodes[i].dim << ", " << t.nodes[i].child << "}"
      << (i + 1 < t.nodes.size() ? ",\n" : "\n");
  o << "};\n";
  o << "static const viscor_sg_patch " << prefix << "_patches[" << t.patches.size() << "] = {\n";
  for (std::size_t i = 0; i < t.patches.size(); ++i) {
    const auto& p = t.patches[i];
    o << "    {" << c_double(p.cx) << ", " << c_double(p.sx) << ", " << c_double(p.cy) << ", " << c_double(p.sy) << "}"
      << (i + 1 < t.patches.size() ? ",\n" : "\n");
  }
  o << "};\n";
  o << "/* by columns: patch p, coefficient of T_i(x) T_j(y) at p n^2 + j n + i (n = " << t.order << ") */\n";
  o << "static const double " << prefix << "_coefficients[" << t.coefficients.size() << "] = {\n"
    << c_doubles(t.coefficients, static_cast<std::size_t>(t.order), "    ") << "};\n";
  return o.str();
}

std::string tree_initializer(const std::string& prefix, const surrogate::patch_tree& t) {
  return "{" + c_double(t.x0) + ", " + c_double(t.x1) + ", " + c_double(t.y0) + ", " + c_double(t.y1) + ", " +
         std::to_string(t.order) + ", " + prefix + "_nodes, " + prefix + "_patches, " + prefix + "_coefficients}";
}

double exponent_value(const std::string& text) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) return std::strtod(text.c_str(), nullptr);
  return std::strtod(text.substr(0, slash).c_str(), nullptr) / std::strtod(text.substr(slash + 1).c_str(), nullptr);
}

// The license of the repository (LICENSE), as a C comment.
constexpr const char* c_license =
    " * SPDX-License-Identifier: MIT\n"
    " *\n"
    " * MIT License\n"
    " *\n"
    " * Copyright (c) 2026 the viscor developers\n"
    " *\n"
    " * Permission is hereby granted, free of charge, to any person obtaining a copy\n"
    " * of this software and associated documentation files (the \"Software\"), to deal\n"
    " * in the Software without restriction, including without limitation the rights\n"
    " * to use, copy, modify, merge, publish, distribute, sublicense, and/or sell\n"
    " * copies of the Software, and to permit persons to whom the Software is\n"
    " * furnished to do so, subject to the following conditions:\n"
    " *\n"
    " * The above copyright notice and this permission notice shall be included in all\n"
    " * copies or substantial portions of the Software.\n"
    " *\n"
    " * THE SOFTWARE IS PROVIDED \"AS IS\", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR\n"
    " * IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,\n"
    " * FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE\n"
    " * AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER\n"
    " * LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM,\n"
    " * OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE\n"
    " * SOFTWARE.\n";

// The comment at the top of both files: what, license, provenance, accuracy.
std::string c_comment(const std::string& file, const std::vector<law_export>& laws) {
  std::ostringstream o;
  o << "/* " << file << ": the coefficient of restitution e of a bead hitting a wall, as fast\n"
    << " * double-precision surrogates of viscor's certified solutions, exported as self-contained\n"
    << " * C99 by `viscor surrogate export --language c` (docs/surrogate.md, \"Exporting to C\").\n"
    << " * Do not edit: export again (the last line seals the file with the SHA-256 of the rest;\n"
    << " * an export replaces only a file whose seal still matches). Needs only the C standard\n"
    << " * library (<math.h>, <float.h>);\n"
    << " * no allocation, no state written (every table is const): safe from any thread.\n"
    << " *\n" << c_license << " *\n"
    << " * Provenance (format: viscor C export 1). Made from these files of viscor's\n"
    << " * reference_data/surrogates/, SHA-256 of each:\n";
  for (const auto& l : laws)
    o << " *   " << l.name << ".surrogate\n *     " << l.surrogate_sha256 << "\n *   " << l.name
      << ".surrogate.verification.csv\n *     " << l.verification_sha256 << "\n";
  o << " *\n"
    << " * Accuracy. The stated bound (per law, the field `bound` of its viscor_surrogate) is the\n"
    << " * measured maximum over the law's 20,000 certified verification points times a safety\n"
    << " * factor of 2, for |e_s - e| where e >= 1e-2, |e_s^2 - e^2| everywhere, and the relative\n"
    << " * error of 1 - e where gamma <= 1e-2 and e >= 1e-2; the outcome is correct except within\n"
    << " * relative 1e-10 in g of the sticking threshold. Measured maxima per region at export\n"
    << " * (this code gives the library's values: docs/surrogate.md, \"Exporting to C\"); the\n"
    << " * regions overlap: small_gamma gamma <= 1e-2, near_threshold within relative 5% in g\n"
    << " * of the threshold, large_g g >= 100, negative_g g < 0:\n"
    << " *   law / region       points   max|de|    max|de^2|  rel d(1-e)  wrong outcomes\n";
  for (const auto& l : laws) {
    o << " *   " << l.name << " (bound: " << c_comment_number(l.s.bound.abs_e) << ", " << c_comment_number(l.s.bound.abs_e_squared) << ", "
      << c_comment_number(l.s.bound.rel_one_minus_e) << ")\n";
    for (const auto& r : l.regions) {
      std::string name = "     " + r.name;
      name.resize(21, ' ');
      std::string pts = std::to_string(r.points);
      pts.insert(0, pts.size() < 6 ? 6 - pts.size() : 0, ' ');
      o << " * " << name << pts << "   " << c_comment_number(r.abs_e) << "   " << c_comment_number(r.abs_e_squared) << "   "
        << c_comment_number(r.rel_one_minus_e) << "        " << r.wrong_outcomes << "\n";
    }
  }
  o << " *\n"
    << " * Model. Scaled: u'' + gamma d/dtau(u^beta) + u^alpha = g while u > 0, u(0) = 0, u'(0) = 1;\n"
    << " * e = -u' when u returns to 0 (rebound), e = 0 if it never does (stick). Physical: a bead\n"
    << " * of mass m hits a rigid wall at speed v0; with the overlap x >= 0,\n"
    << " *   m x'' = -(k x^alpha + gamma0 k d/dt(x^beta)) + m gravity + F,   x(0) = 0, x'(0) = v0,\n"
    << " * gravity (m/s^2) and the force F (N) pushing the bead towards the wall. The scaling\n"
    << " * (viscor's core/scaling.hpp, eq. 2 of the report): x = v0 T u, t = T tau, with\n"
    << " *   T     = (m/k)^(1/(alpha+1)) v0^((1-alpha)/(alpha+1)),\n"
    << " *   gamma = gamma0 v0^(2 beta/(alpha+1) - 1) (k/m)^(1 - beta/(alpha+1)),\n"
    << " *   g     = (m/k)^(1/(alpha+1)) v0^(-2 alpha/(alpha+1)) (gravity + F/m).\n"
    << " * Domain: 0 <= gamma <= gamma_max, g_min <= g <= g_max (viscor_surrogate fields).\n"
    << " */\n";
  return o.str();
}

constexpr const char* c_header_body = R"(
/* The outcome of one impact. */
typedef enum viscor_outcome {
    VISCOR_OUTSIDE_DOMAIN = -1, /* (gamma, g) outside the fitted domain: no value */
    VISCOR_REBOUND = 0,         /* the bead leaves the wall, e > 0 */
    VISCOR_STICK = 1            /* it never leaves: e = 0 */
} viscor_outcome;

/* One evaluation. Outside the domain: outcome VISCOR_OUTSIDE_DOMAIN, the rest NaN. */
typedef struct viscor_cor {
    viscor_outcome outcome;
    double e;           /* 0 for a stick */
    double one_minus_e; /* 1 - e with its relative digits (1 for a stick) */
    double e_squared;   /* 1 - w G before the square root (<= 0 past the threshold) */
} viscor_cor;

/* The stated bound (see the comment at the top). */
typedef struct viscor_sg_bound {
    double abs_e;           /* |e_s - e| where e >= 1e-2 */
    double abs_e_squared;   /* |e_s^2 - e^2| everywhere */
    double rel_one_minus_e; /* relative error of 1 - e where gamma <= 1e-2 and e >= 1e-2 */
    double safety_factor;   /* the measured maximum was multiplied by this */
} viscor_sg_bound;

/* The tables of one law (read-only; the layout of viscor's surrogate/cor_surrogate.hpp). */
typedef struct viscor_sg_node {
    double split; /* inner node: the value of x (dim 0) or y (dim 1) where it splits */
    int dim;      /* 0, 1: inner; 2: leaf */
    int child;    /* inner: the lower child (the upper is child + 1); leaf: the patch */
} viscor_sg_node;
typedef struct viscor_sg_patch {
    double cx, sx, cy, sy; /* (x - cx) sx and (y - cy) sy lie in [-1, 1] */
} viscor_sg_patch;
typedef struct viscor_sg_tree {
    double x0, x1, y0, y1; /* the box */
    int order;             /* Chebyshev points per direction (at most 64) */
    const viscor_sg_node* nodes;
    const viscor_sg_patch* patches;
    const double* coefficients; /* patch p: T_i(x) T_j(y) at p n^2 + j n + i */
} viscor_sg_tree;
typedef struct viscor_surrogate {
    const char* law;              /* the viscor name of the law, e.g. "tsuji" */
    const char* alpha_text;       /* exponents as exact texts, e.g. "3/2" */
    const char* beta_text;
    double alpha, beta;
    double gamma_max, g_min, g_max; /* the domain */
    double gamma_ext, g_split;      /* low loads: g <= g_split (no sticking for gamma <= gamma_max) */
    viscor_sg_bound bound;
    int threshold_order, threshold_breaks;
    const double* threshold_break;        /* breaks in ln g */
    const double* threshold_coefficients; /* interval k: [k order, (k + 1) order) */
    double threshold_power;               /* ln gamma_c = h(ln g) - power ln g */
    viscor_sg_tree low_load;  /* x = gamma, y = g; G = (1 - e^2) / gamma */
    viscor_sg_tree high_load; /* x = ln g, y = sqrt(1 - r), r = gamma / gamma_c(g); G = (1 - e^2) / r */
} viscor_surrogate;

/* The surrogate of the law called `law` ("tsuji", ...), or a null pointer. */
const viscor_surrogate* viscor_surrogate_named(const char* law);

/* Every function below takes a null `s` as a point outside the domain: NaN, or the
   outcome VISCOR_OUTSIDE_DOMAIN with NaN values. */

/* ---- scaled variables ---- */

/* e, 1 - e, e^2 and the outcome at (gamma, g). */
viscor_cor viscor_cor_at(const viscor_surrogate* s, double gamma, double g);
/* e at (gamma, g); NaN outside the domain. */
double viscor_e(const viscor_surrogate* s, double gamma, double g);
/* 1 - e at (gamma, g), with its relative digits as gamma -> 0; NaN outside the domain. */
double viscor_one_minus_e(const viscor_surrogate* s, double gamma, double g);
/* VISCOR_REBOUND, VISCOR_STICK or VISCOR_OUTSIDE_DOMAIN at (gamma, g). */
viscor_outcome viscor_outcome_at(const viscor_surrogate* s, double gamma, double g);
/* The sticking threshold gamma_c(g): the bead sticks for gamma >= gamma_c (to the
   bound on the outcome). HUGE_VAL for g_min <= g <= g_split (no sticking below
   gamma_ext > gamma_max), NaN outside [g_min, g_max]. */
double viscor_critical_gamma(const viscor_surrogate* s, double g);
/* The inverse: the gamma in [0, gamma_max] with e(gamma, g) = e_target, for
   0.01 <= e_target < 1 and g in the domain; NaN if outside those ranges or no gamma
   in the domain reaches e_target. The library's gamma_for, the same bits. */
double viscor_gamma_for(const viscor_surrogate* s, double e_target, double g);

/* ---- physical variables (SI units; see "Model" at the top) ---- */

/* T = (m/k)^(1/(alpha+1)) v0^((1-alpha)/(alpha+1)): physical time = T tau. */
double viscor_time_scale(const viscor_surrogate* s, double m, double k, double v0);
/* gamma / gamma0 = v0^(2 beta/(alpha+1) - 1) (k/m)^(1 - beta/(alpha+1)). */
double viscor_damping_scale(const viscor_surrogate* s, double m, double k, double v0);
/* g / (gravity + F/m) = (m/k)^(1/(alpha+1)) v0^(-2 alpha/(alpha+1)). */
double viscor_load_scale(const viscor_surrogate* s, double m, double k, double v0);
/* The scaled load g of gravity (m/s^2, >= 0: towards the wall) and the force F (N,
   towards the wall; negative: away from it). NaN for a negative or NaN gravity. */
double viscor_scaled_g(const viscor_surrogate* s, double m, double k, double v0, double gravity, double force);
/* The impact of a bead (m > 0, k > 0, gamma0 >= 0, v0 > 0, gravity >= 0): e, 1 - e and
   the outcome (VISCOR_OUTSIDE_DOMAIN, values NaN, for invalid inputs, such as a negative
   gravity, or outside the domain). */
viscor_cor viscor_cor_physical(const viscor_surrogate* s, double m, double k, double gamma0, double v0,
                               double gravity, double force);
/* The damping coefficient gamma0 at which the bead rebounds with e_target
   (0.01 <= e_target < 1) under gravity and F: viscor_gamma_for at the scaled load,
   divided by viscor_damping_scale. NaN for invalid inputs (as viscor_cor_physical) or
   if no gamma in the domain gives e_target. */
double viscor_damping_for(const viscor_surrogate* s, double e_target, double m, double k, double v0,
                          double gravity, double force);
)";

constexpr const char* c_source_body = R"(
#include <float.h>
#include <math.h>

/* NOTE: every product-plus-sum below is written fma(), as in viscor's evaluation
   (surrogate/chebyshev.hpp), and no other product is followed by a sum in one
   expression; each fma is exactly rounded, with or without an FMA instruction. A
   compiler that contracts a * b + c across statements (GCC's -ffp-contract=fast, its
   default in GNU modes where the target has FMA) could change the last bits; ISO C
   modes (-std=c99) and Clang's default do not.

   The FMA instruction without -mfma: compiled for the x86-64 baseline, every fma() is
   a call into libm, most of the cost of an evaluation. With GCC or Clang on x86 the
   evaluation and the inverse are therefore compiled twice, once for AVX2 + FMA, and
   the CPU chooses at run time (as viscor's cor_surrogate does); the helpers are forced
   inline so that each copy is compiled for its caller's target. fma is exactly rounded
   either way: both copies give the same bits. Define VISCOR_SG_NO_DISPATCH for one
   portable copy. */
#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__)) && \
    !defined(_MSC_VER) && !defined(__FMA__) && !defined(VISCOR_SG_NO_DISPATCH)
#define VISCOR_SG_DISPATCH 1
#define VISCOR_SG_INLINE static __inline__ __attribute__((always_inline))
#define VISCOR_SG_FMA_TARGET __attribute__((target("avx2,fma")))
static int viscor_sg_cpu_has_fma(void) {
    __builtin_cpu_init(); /* idempotent; needed when called before the constructors have run */
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}
#else
#define VISCOR_SG_DISPATCH 0
#define VISCOR_SG_INLINE static
#endif

#define VISCOR_SG_MAX_ORDER 64

static int viscor_sg_names_equal(const char* a, const char* b) {
    while (*a && *a == *b) ++a, ++b;
    return *a == *b;
}

/* sum_{j < n} c[j] T_j(x) by Clenshaw's recurrence (chebyshev.hpp, clenshaw). */
VISCOR_SG_INLINE double viscor_sg_clenshaw(const double* c, int n, double x) {
    const double two_x = 2 * x;
    double b1 = 0, b2 = 0;
    int j;
    for (j = n - 1; j >= 1; --j) {
        const double b0 = fma(two_x, b1, c[j] - b2);
        b2 = b1;
        b1 = b0;
    }
    return fma(x, b1, c[0] - b2);
}

/* sum_{i, j < n} t[j n + i] T_i(x) T_j(y): n sums in y, then one in x
   (chebyshev.hpp, clenshaw_2d_by_columns: the same operations per row). */
VISCOR_SG_INLINE double viscor_sg_clenshaw_2d(const double* t, int n, double x, double y) {
    double a[VISCOR_SG_MAX_ORDER], b1[VISCOR_SG_MAX_ORDER], b2[VISCOR_SG_MAX_ORDER];
    const double two_y = 2 * y;
    int i, j;
    for (i = 0; i < n; ++i) b1[i] = 0, b2[i] = 0;
    for (j = n - 1; j >= 1; --j)
        for (i = 0; i < n; ++i) {
            const double b0 = fma(two_y, b1[i], t[j * n + i] - b2[i]);
            b2[i] = b1[i];
            b1[i] = b0;
        }
    for (i = 0; i < n; ++i) a[i] = fma(y, b1[i], t[i] - b2[i]);
    return viscor_sg_clenshaw(a, n, x);
}

/* The patch that holds (x, y): the walk down the k-d tree (patch_tree::walk). */
VISCOR_SG_INLINE int viscor_sg_locate(const viscor_sg_tree* t, double x, double y) {
    int i = 0;
    while (t->nodes[i].dim != 2) {
        const viscor_sg_node* n = &t->nodes[i];
        const double v = n->dim == 0 ? x : y;
        i = n->child + (v >= n->split ? 1 : 0);
    }
    return t->nodes[i].child;
}

/* The interpolant at (x, y) in the box (patch_tree::value). */
VISCOR_SG_INLINE double viscor_sg_tree_value(const viscor_sg_tree* t, double x, double y) {
    const int p = viscor_sg_locate(t, x, y), n = t->order;
    const viscor_sg_patch* q = &t->patches[p];
    const double* c = t->coefficients + (long)p * n * n;
    const double u = (x - q->cx) * q->sx, v = (y - q->cy) * q->sy;
    if (n == 12) return viscor_sg_clenshaw_2d(c, 12, u, v); /* the committed order, unrolled */
    return viscor_sg_clenshaw_2d(c, n, u, v);
}

/* h(x) = ln gamma_c + power ln g at x = ln g (patch_line). */
VISCOR_SG_INLINE double viscor_sg_threshold_line(const viscor_surrogate* s, double x) {
    int k = 0, m;
    double a, b;
    for (m = 1; m <= s->threshold_breaks - 2; ++m) k += x >= s->threshold_break[m] ? 1 : 0;
    a = s->threshold_break[k], b = s->threshold_break[k + 1];
    return viscor_sg_clenshaw(s->threshold_coefficients + k * s->threshold_order, s->threshold_order,
                              (2 * x - a - b) / (b - a));
}

/* gamma_c(g) given x = ln g (cor_surrogate::critical_gamma_at). */
VISCOR_SG_INLINE double viscor_sg_critical_gamma_at(const viscor_surrogate* s, double g, double x) {
    const double h = exp(viscor_sg_threshold_line(s, x));
    return s->threshold_power == 0 ? h : h * pow(g, -s->threshold_power);
}

VISCOR_SG_INLINE viscor_cor viscor_sg_stick(double e_squared) {
    viscor_cor v;
    v.outcome = VISCOR_STICK;
    v.e = 0, v.one_minus_e = 1, v.e_squared = e_squared;
    return v;
}

VISCOR_SG_INLINE viscor_cor viscor_sg_cor_at(const viscor_surrogate* s, double gamma, double g) {
    viscor_cor v;
    double w = gamma, G, dissipated;
    if (!s || !(gamma >= 0 && gamma <= s->gamma_max && g >= s->g_min && g <= s->g_max)) { /* also NaN */
        v.outcome = VISCOR_OUTSIDE_DOMAIN;
        v.e = NAN, v.one_minus_e = NAN, v.e_squared = NAN;
        return v;
    }
    if (g <= s->g_split) {
        G = viscor_sg_tree_value(&s->low_load, gamma, g);
    } else {
        const double x = log(g);
        const double r = gamma / viscor_sg_critical_gamma_at(s, g, x);
        if (r >= 1) return viscor_sg_stick(1 - r);
        w = r;
        G = viscor_sg_tree_value(&s->high_load, x, sqrt(1 - r));
    }
    dissipated = w * G; /* 1 - e^2 */
    v.e_squared = 1 - dissipated;
    if (!(v.e_squared > 0)) return viscor_sg_stick(v.e_squared);
    v.outcome = VISCOR_REBOUND;
    v.e = sqrt(v.e_squared);
    v.one_minus_e = dissipated / (1 + v.e);
    return v;
}

#if VISCOR_SG_DISPATCH
VISCOR_SG_FMA_TARGET static viscor_cor viscor_sg_cor_at_fma(const viscor_surrogate* s, double gamma, double g) {
    return viscor_sg_cor_at(s, gamma, g);
}
#endif

viscor_cor viscor_cor_at(const viscor_surrogate* s, double gamma, double g) {
#if VISCOR_SG_DISPATCH
    if (viscor_sg_cpu_has_fma()) return viscor_sg_cor_at_fma(s, gamma, g);
#endif
    return viscor_sg_cor_at(s, gamma, g);
}

double viscor_e(const viscor_surrogate* s, double gamma, double g) { return viscor_cor_at(s, gamma, g).e; }

double viscor_one_minus_e(const viscor_surrogate* s, double gamma, double g) {
    return viscor_cor_at(s, gamma, g).one_minus_e;
}

viscor_outcome viscor_outcome_at(const viscor_surrogate* s, double gamma, double g) {
    return viscor_cor_at(s, gamma, g).outcome;
}

double viscor_critical_gamma(const viscor_surrogate* s, double g) {
    if (!s || !(g >= s->g_min && g <= s->g_max)) return NAN;
    if (g <= s->g_split) return HUGE_VAL;
    return viscor_sg_critical_gamma_at(s, g, log(g));
}

/* ---- the inverse (cor_surrogate::inverse, solve_dissipation, slice) ---- */

/* One patch restricted to a line of its fixed coordinate: G as a Chebyshev series in
   t = (z - c) s on [lo, hi] of the free coordinate z. */
typedef struct viscor_sg_slice {
    int patch;
    double c, s, lo, hi;
    int n;
    double a[VISCOR_SG_MAX_ORDER];
} viscor_sg_slice;

VISCOR_SG_INLINE void viscor_sg_slice_build(viscor_sg_slice* sl, const viscor_sg_tree* tree, int x_free, double fixed, double z) {
    const viscor_sg_patch* q;
    const double* coef;
    double T[VISCOR_SG_MAX_ORDER], u;
    int N, i, j, k;
    sl->patch = x_free ? viscor_sg_locate(tree, z, fixed) : viscor_sg_locate(tree, fixed, z);
    q = &tree->patches[sl->patch];
    N = tree->order;
    sl->n = N;
    coef = tree->coefficients + (long)sl->patch * N * N;
    u = x_free ? (fixed - q->cy) * q->sy : (fixed - q->cx) * q->sx;
    T[0] = 1, T[1] = u;
    for (k = 2; k < N; ++k) T[k] = fma(2 * u, T[k - 1], -T[k - 2]);
    for (i = 0; i < N; ++i) sl->a[i] = 0;
    if (x_free) {
        for (i = 0; i < N; ++i)
            for (j = 0; j < N; ++j) sl->a[i] = fma(coef[j * N + i], T[j], sl->a[i]);
        sl->c = q->cx, sl->s = q->sx;
    } else {
        for (i = 0; i < N; ++i)
            for (j = 0; j < N; ++j) sl->a[j] = fma(coef[j * N + i], T[i], sl->a[j]);
        sl->c = q->cy, sl->s = q->sy;
    }
    sl->lo = sl->c - 1 / sl->s, sl->hi = sl->c + 1 / sl->s;
}

/* G and dG/dz at z (Clenshaw with its derivative). */
VISCOR_SG_INLINE void viscor_sg_slice_value(const viscor_sg_slice* sl, double z, double* G, double* dG) {
    const double t = (z - sl->c) * sl->s, two_t = 2 * t;
    double b1 = 0, b2 = 0, d1 = 0, d2 = 0;
    int k;
    for (k = sl->n - 1; k >= 1; --k) {
        const double b0 = fma(two_t, b1, sl->a[k] - b2);
        const double d0 = fma(two_t, d1, 2 * b1 - d2);
        b2 = b1, b1 = b0, d2 = d1, d1 = d0;
    }
    *G = fma(t, b1, sl->a[0] - b2);
    *dG = (fma(t, d1, b1) - d2) * sl->s;
}

/* f(w) = w G(w) - D on the line of fixed coordinate `fixed`, and *df = f'(w); z = w
   (low loads, x_free) or z = sqrt(1 - w) (high loads). */
VISCOR_SG_INLINE double viscor_sg_residual(const viscor_sg_tree* tree, int x_free, double fixed, double D, viscor_sg_slice* sl,
                                 double w, double* df) {
    const double z = x_free ? w : sqrt(1 - w);
    const double lo = x_free ? tree->x0 : tree->y0, hi = x_free ? tree->x1 : tree->y1;
    const double zl = z < lo ? lo : z;       /* std::max(z, lo) */
    const double zc = hi < zl ? hi : zl;     /* std::min(zl, hi) */
    double G, dGdz, dGdw;
    if (!(sl->patch >= 0 && zc >= sl->lo && zc < sl->hi)) viscor_sg_slice_build(sl, tree, x_free, fixed, zc);
    viscor_sg_slice_value(sl, z, &G, &dGdz);
    dGdw = x_free ? dGdz : (z > 0 ? -dGdz / (2 * z) : 0.0);
    *df = fma(w, dGdw, G);
    return fma(w, G, -D);
}

/* The w in [0, b] with w G(w) = D: Newton inside a shrinking bracket. NaN if b G(b) < D. */
VISCOR_SG_INLINE double viscor_sg_solve(const viscor_sg_tree* tree, int x_free, double fixed, double D, double b) {
    const double eps = DBL_EPSILON;
    viscor_sg_slice sl;
    double df = 0, neg = 0, pos = b, w, q;
    int i;
    sl.patch = -1, sl.c = 0, sl.s = 1, sl.lo = 0, sl.hi = 0, sl.n = 0;
    if (viscor_sg_residual(tree, x_free, fixed, D, &sl, b, &df) < 0) return NAN;
    viscor_sg_residual(tree, x_free, fixed, D, &sl, 0, &df); /* df = G(0) */
    q = D / df;
    w = b < q ? b : q; /* std::min(D / df, b) */
    for (i = 0; i < 40; ++i) {
        const double fw = viscor_sg_residual(tree, x_free, fixed, D, &sl, w, &df);
        double next;
        if (fw == 0) return w;
        if (fw < 0) neg = w; else pos = w;
        next = w - fw / df;
        if (fabs(next - w) <= 2 * eps * w) return next;
        if (!(next > neg && next < pos)) next = (neg + pos) / 2; /* safeguard */
        if (pos - neg <= 2 * eps * pos) return next;
        w = next;
    }
    return w;
}

VISCOR_SG_INLINE double viscor_sg_gamma_for(const viscor_surrogate* s, double e_target, double g) {
    double dissipated, x, gc, top;
    if (!s || !(e_target >= 0.01 && e_target < 1) || !(g >= s->g_min && g <= s->g_max)) return NAN;
    dissipated = (1 - e_target) * (1 + e_target);
    if (!(dissipated > 0)) return 0;
    if (g <= s->g_split) return viscor_sg_solve(&s->low_load, 1, g, dissipated, s->gamma_max);
    x = log(g);
    gc = viscor_sg_critical_gamma_at(s, g, x);
    top = s->gamma_max / gc;
    return viscor_sg_solve(&s->high_load, 0, x, dissipated, top < 1.0 ? top : 1.0) * gc;
}

#if VISCOR_SG_DISPATCH
VISCOR_SG_FMA_TARGET static double viscor_sg_gamma_for_fma(const viscor_surrogate* s, double e_target, double g) {
    return viscor_sg_gamma_for(s, e_target, g);
}
#endif

double viscor_gamma_for(const viscor_surrogate* s, double e_target, double g) {
#if VISCOR_SG_DISPATCH
    if (viscor_sg_cpu_has_fma()) return viscor_sg_gamma_for_fma(s, e_target, g);
#endif
    return viscor_sg_gamma_for(s, e_target, g);
}

/* ---- physical variables (core/scaling.hpp: the same expressions) ---- */

double viscor_time_scale(const viscor_surrogate* s, double m, double k, double v0) {
    double alpha;
    if (!s) return NAN;
    alpha = s->alpha;
    return pow(m / k, 1 / (alpha + 1)) * pow(v0, (1 - alpha) / (alpha + 1));
}

double viscor_damping_scale(const viscor_surrogate* s, double m, double k, double v0) {
    double alpha, beta;
    if (!s) return NAN;
    alpha = s->alpha, beta = s->beta;
    return pow(v0, 2 * beta / (alpha + 1) - 1) * pow(k / m, 1 - beta / (alpha + 1));
}

double viscor_load_scale(const viscor_surrogate* s, double m, double k, double v0) {
    double alpha;
    if (!s) return NAN;
    alpha = s->alpha;
    return pow(m / k, 1 / (alpha + 1)) * pow(v0, -2 * alpha / (alpha + 1));
}

double viscor_scaled_g(const viscor_surrogate* s, double m, double k, double v0, double gravity, double force) {
    const double acceleration = gravity + force / m;
    if (!(gravity >= 0)) return NAN;
    return viscor_load_scale(s, m, k, v0) * acceleration;
}

static int viscor_sg_valid_bead(double m, double k, double v0, double gravity, double force) {
    return m > 0 && k > 0 && v0 > 0 && m <= DBL_MAX && k <= DBL_MAX && v0 <= DBL_MAX && gravity >= 0 &&
           force == force;
}

viscor_cor viscor_cor_physical(const viscor_surrogate* s, double m, double k, double gamma0, double v0,
                               double gravity, double force) {
    if (!s || !viscor_sg_valid_bead(m, k, v0, gravity, force) || !(gamma0 >= 0)) {
        viscor_cor v;
        v.outcome = VISCOR_OUTSIDE_DOMAIN;
        v.e = NAN, v.one_minus_e = NAN, v.e_squared = NAN;
        return v;
    }
    return viscor_cor_at(s, gamma0 * viscor_damping_scale(s, m, k, v0), viscor_scaled_g(s, m, k, v0, gravity, force));
}

double viscor_damping_for(const viscor_surrogate* s, double e_target, double m, double k, double v0,
                          double gravity, double force) {
    if (!s || !viscor_sg_valid_bead(m, k, v0, gravity, force)) return NAN;
    return viscor_gamma_for(s, e_target, viscor_scaled_g(s, m, k, v0, gravity, force)) /
           viscor_damping_scale(s, m, k, v0);
}
)";

}  // namespace detail

std::vector<exported_file> surrogate_export_files(const surrogate_export_options& options) {
  if (options.language != "c")
    throw invalid_parameter("surrogate export: language '" + options.language + "' is not supported (only c)");
  const auto names = detail::export_law_names(options);
  std::vector<detail::law_export> laws;
  for (const auto& name : names) laws.push_back(detail::read_law_export(options.surrogate_directory, name));
  const bool all = options.laws.empty() || (options.laws.size() == 1 && options.laws[0] == "all");
  const std::string base = all ? "viscor_surrogates" : names.size() == 1 ? "viscor_surrogate_" + names[0] : "viscor_surrogates";
  std::string guard;
  for (const char c : base) guard += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  guard += "_H";

  std::ostringstream h;
  h << detail::c_comment(base + ".h", laws) << "#ifndef " << guard << "\n#define " << guard << "\n\n"
    << "#ifdef __cplusplus\nextern \"C\" {\n#endif\n" << detail::c_header_body << dem_entries_c_declarations()
    << "\n/* The laws of this export. */\n";
  for (const auto& l : laws)
    h << "extern const viscor_surrogate viscor_surrogate_" << l.name << "; /* alpha = " << l.s.alpha
      << ", beta = " << l.s.beta << " */\n";
  h << "\n#ifdef __cplusplus\n}\n#endif\n\n#endif /* " << guard << " */\n";

  std::ostringstream c;
  c << detail::c_comment(base + ".c", laws) << "#include \"" << base << ".h\"\n" << detail::c_source_body
    << dem_entries_c_definitions();
  for (const auto& l : laws) {
    const std::string p = "viscor_sg_" + l.name;
    const auto& s = l.s;
    c << "\n/* ---- " << l.name << " (alpha = " << s.alpha << ", beta = " << s.beta << ") ---- */\n\n";
    c << "static const double " << p << "_threshold_break[" << s.log_gamma_c.breaks.size() << "] = {\n"
      << detail::c_doubles(s.log_gamma_c.breaks, 4, "    ") << "};\n";
    c << "static const double " << p << "_threshold_coefficients[" << s.log_gamma_c.coefficients.size() << "] = {\n"
      << detail::c_doubles(s.log_gamma_c.coefficients, 4, "    ") << "};\n";
    c << detail::tree_data(p + "_low", s.low_load) << detail::tree_data(p + "_high", s.high_load);
    c << "const viscor_surrogate viscor_surrogate_" << l.name << " = {\n"
      << "    \"" << l.name << "\", \"" << s.alpha << "\", \"" << s.beta << "\", "
      << detail::c_double(detail::exponent_value(s.alpha)) << ", " << detail::c_double(detail::exponent_value(s.beta))
      << ",\n    " << detail::c_double(s.gamma_max) << ", " << detail::c_double(s.g_min) << ", "
      << detail::c_double(s.g_max) << ", " << detail::c_double(s.gamma_ext) << ", " << detail::c_double(s.g_split)
      << ",\n    {" << detail::c_double(s.bound.abs_e) << ", " << detail::c_double(s.bound.abs_e_squared) << ", "
      << detail::c_double(s.bound.rel_one_minus_e) << ", " << detail::c_double(s.bound.safety_factor) << "},\n    "
      << s.log_gamma_c.order << ", " << s.log_gamma_c.breaks.size() << ", " << p << "_threshold_break, " << p
      << "_threshold_coefficients, " << detail::c_double(s.threshold_power) << ",\n    "
      << detail::tree_initializer(p + "_low", s.low_load) << ",\n    "
      << detail::tree_initializer(p + "_high", s.high_load) << "\n};\n";
  }
  c << "\nconst viscor_surrogate* viscor_surrogate_named(const char* law) {\n";
  for (const auto& l : laws)
    c << "    if (law && viscor_sg_names_equal(law, \"" << l.name << "\")) return &viscor_surrogate_" << l.name << ";\n";
  c << "    return 0;\n}\n";
  return {{base + ".h", sealed(h.str(), c_comment_seal)}, {base + ".c", sealed(c.str(), c_comment_seal)}};
}

std::string exported_file_marker(const std::string& name) { return "/* " + name + ": "; }

std::vector<std::string> export_surrogates(const surrogate_export_options& options) {
  if (options.output_directory.empty()) throw invalid_parameter("surrogate export needs an output directory: -o DIR");
  const auto files = surrogate_export_files(options);
  std::error_code ec;
  if (std::filesystem::exists(options.output_directory, ec) && !std::filesystem::is_directory(options.output_directory, ec))
    throw invalid_parameter("surrogate export: output '" + options.output_directory + "' exists and is not a directory");
  std::filesystem::create_directories(options.output_directory, ec);
  if (ec) throw error("surrogate export: cannot create the directory '" + options.output_directory + "': " + ec.message());
  std::vector<std::string> paths;
  std::vector<output_file> outputs;
  for (const auto& f : files) {
    const std::string path = options.output_directory + "/" + f.name;
    refuse_unless_own_or_absent(path, exported_file_marker(f.name), "surrogate export -o", "an export",
                                c_comment_seal, max_exported_file_size);
    outputs.push_back({path, f.text});
    paths.push_back(path);
  }
  write_together(outputs);
  return paths;
}

}  // namespace viscor::jobs
