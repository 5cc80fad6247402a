#!/usr/bin/env python3
"""The operation floor of a 50-digit solve (docs/performance.md, "The 50-digit floor").

Counts the MPFR calls that solve_impact<mpfr_50> makes per CoR, by function, measures
what each such call costs on its own at the same precision, and compares the sum
(the floor: the solve's MPFR work with nothing around it) with the solve's time.

How: the MPFR functions are interposed by a small preloaded library (generated here
from the functions libmpfr exports): each entry point counts its call when it is not
made from inside another MPFR call (so a pow is one pow, not also the logs and exps
it makes), then jumps to MPFR. A driver (solve_driver.cpp) brackets N solves with
the library's reset and dump hooks. Costs come from a generated micro-benchmark that
calls each counted function on operands of the solve's precision, with exponents and
signs spread as along a Taylor series.

Usage: tools/mpfr_floor/mpfr_floor.py [BUILD_DIR] [--solves N]
  BUILD_DIR: a configured and built viscor build tree (default build), for
  include/viscor/config.hpp and libviscor.a.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
LIBMPFR = "/lib/x86_64-linux-gnu/libmpfr.so.6"

# Variadic functions are left alone (the entry point keeps the stack as it is, but
# a va_list walk through a jump is not worth the risk for output functions).
NOT_WRAPPED = re.compile(r"printf|scanf")

# How to call each kind of function in the micro-benchmark: C statements over
# x, y, z (operands), r (result), u (unsigned long 3), s (long -3), d (double 1.25).
CALLS = {}
for f in ["add", "sub", "mul", "div", "pow", "atan2", "hypot", "min", "max", "agm", "dim", "fmod", "remainder"]:
    CALLS[f] = "mpfr_%s(r, x, y, MPFR_RNDN)" % f
for f in ["sqrt", "log", "exp", "neg", "abs", "set", "sqr", "log1p", "expm1", "cbrt", "sin", "cos", "tan",
          "rec_sqrt", "log2", "log10", "exp2", "atan", "sinh", "cosh", "tanh", "rint", "frac"]:
    CALLS[f] = "mpfr_%s(r, x, MPFR_RNDN)" % f
for f in ["mul_ui", "add_ui", "sub_ui", "div_ui", "pow_ui", "mul_2ui", "div_2ui", "rootn_ui", "root"]:
    CALLS[f] = "mpfr_%s(r, x, u, MPFR_RNDN)" % f
for f in ["mul_si", "add_si", "sub_si", "div_si", "pow_si", "mul_2si", "div_2si", "mul_2exp", "div_2exp"]:
    CALLS[f] = "mpfr_%s(r, x, s, MPFR_RNDN)" % f
for f in ["mul_d", "add_d", "sub_d", "div_d"]:
    CALLS[f] = "mpfr_%s(r, x, d, MPFR_RNDN)" % f
for f in ["ui_div", "ui_sub", "ui_pow"]:
    CALLS[f] = "mpfr_%s(r, u, x, MPFR_RNDN)" % f
CALLS.update({
    "set_ui": "mpfr_set_ui(r, u, MPFR_RNDN)", "set_si": "mpfr_set_si(r, s, MPFR_RNDN)",
    "set_d": "mpfr_set_d(r, d, MPFR_RNDN)", "set_ui_2exp": "mpfr_set_ui_2exp(r, u, -3, MPFR_RNDN)",
    "set_si_2exp": "mpfr_set_si_2exp(r, s, -3, MPFR_RNDN)",
    "fma": "mpfr_fma(r, x, y, z, MPFR_RNDN)", "fms": "mpfr_fms(r, x, y, z, MPFR_RNDN)",
    "cmp": "sink += mpfr_cmp(x, y)", "cmp_ui": "sink += mpfr_cmp_ui(x, u)", "cmp_si": "sink += mpfr_cmp_si(x, s)",
    "cmp_d": "sink += mpfr_cmp_d(x, d)", "cmpabs": "sink += mpfr_cmpabs(x, y)",
    "cmp_ui_2exp": "sink += mpfr_cmp_ui_2exp(x, u, -3)", "cmp_si_2exp": "sink += mpfr_cmp_si_2exp(x, s, -3)",
    "equal_p": "sink += mpfr_equal_p(x, y)", "less_p": "sink += mpfr_less_p(x, y)",
    "greater_p": "sink += mpfr_greater_p(x, y)", "lessequal_p": "sink += mpfr_lessequal_p(x, y)",
    "greaterequal_p": "sink += mpfr_greaterequal_p(x, y)", "unordered_p": "sink += mpfr_unordered_p(x, y)",
    "get_d": "sink += (long)mpfr_get_d(x, MPFR_RNDN)", "get_si": "sink += mpfr_get_si(x, MPFR_RNDN)",
    "get_ui": "sink += (long)mpfr_get_ui(x, MPFR_RNDN)", "get_exp": "sink += mpfr_get_exp(x)",
    "get_prec": "sink += mpfr_get_prec(x)", "sgn": "sink += mpfr_sgn(x)",
    "nan_p": "sink += mpfr_nan_p(x)", "inf_p": "sink += mpfr_inf_p(x)", "zero_p": "sink += mpfr_zero_p(x)",
    "number_p": "sink += mpfr_number_p(x)", "regular_p": "sink += mpfr_regular_p(x)",
    "integer_p": "sink += mpfr_integer_p(x)", "signbit": "sink += mpfr_signbit(x)",
    "floor": "mpfr_floor(r, x)", "ceil": "mpfr_ceil(r, x)", "trunc": "mpfr_trunc(r, x)", "round": "mpfr_round(r, x)",
    "swap": "mpfr_swap(r, z)", "set_nan": "mpfr_set_nan(r)", "set_zero": "mpfr_set_zero(r, 1)",
    "set_inf": "mpfr_set_inf(r, 1)", "const_pi": "mpfr_const_pi(r, MPFR_RNDN)",
    "const_log2": "mpfr_const_log2(r, MPFR_RNDN)",
    "get_default_prec": "sink += mpfr_get_default_prec()", "get_emin": "sink += mpfr_get_emin()",
    "get_emax": "sink += mpfr_get_emax()", "clear_flags": "mpfr_clear_flags()",
    # init2 and clear are paired (a temporary is made and dropped): their pair's cost, half each.
    "init2": "{ mpfr_t t; mpfr_init2(t, PREC); mpfr_clear(t); }",
    "clear": "{ mpfr_t t; mpfr_init2(t, PREC); mpfr_clear(t); }",
    "set_prec": "mpfr_set_prec(r, PREC)", "set4": "mpfr_set4(r, x, MPFR_RNDN, 1)",
    "get_d_2exp": "{ long e; sink += (long)mpfr_get_d_2exp(&e, x, MPFR_RNDN) + e; }",
    "fits_intmax_p": "sink += mpfr_fits_intmax_p(x, MPFR_RNDN)",
})
PAIRED_HALF = {"init2", "clear"}


def run(cmd, **kw):
    return subprocess.run(cmd, check=True, text=True, capture_output=True, **kw).stdout


def exported_functions():
    names = []
    for line in run(["nm", "-D", "--defined-only", LIBMPFR]).splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[1] == "T" and parts[2].startswith("mpfr_") and not NOT_WRAPPED.search(parts[2]):
            names.append(parts[2].split("@")[0])
    return sorted(set(names))


def counting_library(names, work):
    """C source of the preloaded library: one counting entry point per function."""
    n = len(names)
    out = ["#define _GNU_SOURCE", "#include <dlfcn.h>", "#include <stdio.h>", "#include <stdlib.h>",
           "#include <string.h>",
           "__attribute__((visibility(\"hidden\"))) unsigned long mpfr_floor_depth;",
           "__attribute__((visibility(\"hidden\"))) unsigned long mpfr_floor_top[%d];" % n,
           "__attribute__((visibility(\"hidden\"))) void* mpfr_floor_real[%d];" % n,
           "static const char* const names[%d] = {%s};" % (n, ", ".join('"%s"' % x for x in names)),
           "__attribute__((constructor)) static void resolve(void) {",
           "  for (int i = 0; i < %d; ++i) mpfr_floor_real[i] = dlsym(RTLD_NEXT, names[i]);" % n, "}",
           "void mpfr_floor_reset(void) { memset(mpfr_floor_top, 0, sizeof mpfr_floor_top); }",
           "void mpfr_floor_dump(void) {",
           "  FILE* f = fopen(getenv(\"MPFR_FLOOR_OUT\"), \"a\");",
           "  for (int i = 0; i < %d; ++i) if (mpfr_floor_top[i]) fprintf(f, \"%%s %%lu\\n\", names[i], mpfr_floor_top[i]);" % n,
           "  fprintf(f, \"--\\n\");", "  fclose(f);", "  mpfr_floor_reset();", "}"]
    # Entry: the caller's return address goes to a shadow stack and is replaced by the
    # exit below, the depth goes up (counted if outermost), then a jump into MPFR with
    # the stack exactly as the caller left it (arguments on the stack stay where they
    # are). Exit: depth down, back to the saved address. Return values (rax, rdx, xmm0,
    # st0) are not touched; r10 and r11 are scratch registers of the calling convention.
    out.insert(6, "__attribute__((visibility(\"hidden\"))) unsigned long mpfr_floor_shadow[65536];")
    out.insert(7, "__attribute__((visibility(\"hidden\"))) unsigned long* mpfr_floor_sp = mpfr_floor_shadow;")
    for i, name in enumerate(names):
        out.append("__attribute__((naked)) void %s(void) { __asm__(" % name)
        out.append('  "movq (%%rsp), %%r11\\n movq mpfr_floor_sp(%%rip), %%r10\\n movq %%r11, (%%r10)\\n'
                   ' addq $8, mpfr_floor_sp(%%rip)\\n leaq 2f(%%rip), %%r11\\n movq %%r11, (%%rsp)\\n'
                   ' incq mpfr_floor_depth(%%rip)\\n cmpq $1, mpfr_floor_depth(%%rip)\\n jne 1f\\n'
                   ' incq mpfr_floor_top+%d(%%rip)\\n1:\\n jmp *mpfr_floor_real+%d(%%rip)\\n'
                   '2:\\n decq mpfr_floor_depth(%%rip)\\n subq $8, mpfr_floor_sp(%%rip)\\n'
                   ' movq mpfr_floor_sp(%%rip), %%r10\\n jmp *(%%r10)\\n"); }' % (8 * i, 8 * i))
    src = os.path.join(work, "count_mpfr.c")
    with open(src, "w") as f:
        f.write("\n".join(out) + "\n")
    lib = os.path.join(work, "libcount_mpfr.so")
    run(["cc", "-O2", "-shared", "-fPIC", "-o", lib, src, "-ldl"])
    return lib


def micro_benchmark(functions, prec, work):
    """ns per call of each function at `prec` bits (CPU time, operands spread like a solve's)."""
    body = []
    for name in functions:
        short = name[len("mpfr_"):]
        reps = 20000 if short in ("pow", "log", "exp", "atan2", "sin", "cos", "tan", "log1p", "expm1", "root",
                                  "rootn_ui", "agm", "sinh", "cosh", "tanh", "atan", "log2", "log10", "exp2",
                                  "cbrt", "hypot", "pow_si", "pow_ui", "ui_pow") else 400000
        body.append('  { double t0 = cpu(); for (long i = 0; i < %d; ++i) { %s; } '
                    'printf("%s %%.2f\\n", 1e9 * (cpu() - t0) / %d); }' % (reps, CALLS[short], name, reps))
    src = os.path.join(work, "cost.c")
    with open(src, "w") as f:
        f.write("""#include <mpfr.h>
#include <stdio.h>
#include <time.h>
#define PREC %d
static double cpu(void) { struct timespec t; clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t); return t.tv_sec + 1e-9 * t.tv_nsec; }
int main(void) {
  /* Operands like a solve's: 64 of each, exponents spread over 2^-40..2^1 (Taylor
     coefficients shrink along a series), y and z of either sign (so additions also
     subtract and cancel), taken in an order the branch predictor cannot learn. */
  mpfr_t X[64], Y[64], Z[64], r; unsigned long u = 3; long s = -3; double d = 1.25; volatile long sink = 0;
  unsigned long long seed = 88172645463325252ull;
  mpfr_init2(r, PREC);
  for (int k = 0; k < 64; ++k) {
    mpfr_t* v[3] = {&X[k], &Y[k], &Z[k]};
    for (int j = 0; j < 3; ++j) {
      mpfr_init2(*v[j], PREC);
      mpfr_set_ui(*v[j], 0, MPFR_RNDN);
      for (int w = 0; w < 3; ++w) {  /* a full-precision mantissa from three 64-bit draws */
        seed ^= seed << 13, seed ^= seed >> 7, seed ^= seed << 17;
        mpfr_mul_2ui(*v[j], *v[j], 64, MPFR_RNDN);
        mpfr_add_ui(*v[j], *v[j], (unsigned long)seed, MPFR_RNDN);
      }
      mpfr_mul_2si(*v[j], *v[j], -192 - (long)(seed %% 41), MPFR_RNDN);
      if (j > 0 && (seed >> 40) %% 2) mpfr_neg(*v[j], *v[j], MPFR_RNDN);
    }
  }
#define x X[(i * 37 + 11) & 63]
#define y Y[(i * 23 + 5) & 63]
#define z Z[(i * 29 + 3) & 63]
%s
  (void)sink; return 0;
}
""" % (prec, "\n".join(body)))
    exe = os.path.join(work, "cost")
    run(["cc", "-O2", "-o", exe, src, "-lmpfr", "-lgmp"])
    costs = {}
    for line in run([exe]).splitlines():
        name, ns = line.split()
        costs[name] = float(ns) / (2 if name[len("mpfr_"):] in PAIRED_HALF else 1)
    return costs


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build", nargs="?", default="build")
    ap.add_argument("--solves", type=int, default=20)
    a = ap.parse_args()
    build = os.path.abspath(a.build)
    work = tempfile.mkdtemp(prefix="viscor-mpfr-floor.")
    driver = os.path.join(work, "solve_driver")
    run(["g++", "-O3", "-DNDEBUG", "-std=c++20", "-I", os.path.join(ROOT, "include"), "-I", os.path.join(build, "include"),
         os.path.join(HERE, "solve_driver.cpp"), os.path.join(build, "libviscor.a"), "-o", driver,
         "-lmpfr", "-lgmp", "-ldl"])
    lib = counting_library(exported_functions(), work)
    counts_file = os.path.join(work, "counts.txt")
    env = dict(os.environ, LD_PRELOAD=lib, MPFR_FLOOR_OUT=counts_file)
    run([driver, str(a.solves)], env=env)  # counts (the timings of this run are not used)
    timed = run([driver, str(a.solves)])     # times, without the counting library
    points = [dict(kv.split("=") for kv in line.split()[1:]) for line in timed.splitlines()]
    blocks = open(counts_file).read().split("--\n")[:len(points)]
    for point, block in zip(points, blocks):
        counts = {n: int(c) / a.solves for n, c in (l.split() for l in block.splitlines())}
        costs = micro_benchmark([n for n in counts if n[len("mpfr_"):] in CALLS], int(point["bits"]), work)
        rows = sorted(counts.items(), key=lambda kv: -kv[1] * costs.get(kv[0], 0))
        floor_ns = sum(c * costs.get(n, 0) for n, c in counts.items())
        unpriced = {n: c for n, c in counts.items() if n not in costs}
        print("kuwabara_kono gamma=%s g=%s, %s bits, %s steps, %d solves: solve %.0f us CPU (median)" %
              (point["gamma"], point["g"], point["bits"], point["steps"], a.solves, float(point["median_us"])))
        print("| MPFR function | calls per solve | ns per call | us per solve | share of the floor |")
        print("|---|---|---|---|---|")
        for n, c in rows:
            if n in costs:
                print("| `%s` | %.0f | %.1f | %.1f | %.1f%% |" % (n, c, costs[n], c * costs[n] / 1e3,
                                                             100 * c * costs[n] / floor_ns))
        print("| **all counted** | %.0f | | **%.0f** | |" % (sum(counts.values()), floor_ns / 1e3))
        if unpriced:
            print("not priced (no micro-benchmark): " + ", ".join("%s %.0f" % kv for kv in sorted(unpriced.items())))
        print("solve / floor = %.2f\n" % (float(point["median_us"]) * 1e3 / floor_ns))


if __name__ == "__main__":
    sys.exit(main())
