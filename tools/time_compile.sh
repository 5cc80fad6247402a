#!/bin/sh
# Compiler and linker launcher that records the CPU time of every compile and
# link (docs/performance.md, "Build time"). Its first argument is the log file
# (an absolute path: the build runs the commands from several directories). Use
# it instead of ccache (a cache hit would hide the compile), in an empty build
# directory:
#   cmake -S . -B DIR -DCMAKE_CXX_COMPILER_LAUNCHER="$PWD/tools/time_compile.sh;$PWD/DIR/times.log" \
#                     -DCMAKE_CXX_LINKER_LAUNCHER="$PWD/tools/time_compile.sh;$PWD/DIR/times.log"
#   cmake --build DIR -j2 --target viscor_cli
#   python3 tools/build_time_report.py DIR/times.log
# Each line of the log: user seconds, system seconds, wall seconds, output file.
log="$1"
shift
out="?"
previous=""
for arg in "$@"; do
  [ "$previous" = "-o" ] && out="$arg"
  previous="$arg"
done
exec /usr/bin/time -a -o "$log" -f "%U %S %e $out" "$@"
