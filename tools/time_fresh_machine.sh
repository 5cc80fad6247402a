#!/usr/bin/env bash
# Times the README's main-job command on a fresh Debian 12 system
# (docs/performance.md, "On a fresh machine"): a minimal Debian made by debootstrap (no
# compiler, no CMake, no libraries), a fresh clone of this repository in it, and the
# command run as written, packages included. Needs root, debootstrap and network
# access to a Debian mirror; leaves everything under WORKDIR (delete it afterwards:
# `umount WORKDIR/root/proc WORKDIR/root/dev; rm -rf WORKDIR`).
#   sudo tools/time_fresh_machine.sh WORKDIR
set -euo pipefail

[ $# -eq 1 ] || { echo "usage: $0 WORKDIR (an empty or missing directory)" >&2; exit 2; }
work="$1"
repo="$(cd "$(dirname "$0")/.." && pwd)"
root="$work/root"
[ ! -e "$root" ] || { echo "time_fresh_machine: $root exists; give an empty WORKDIR" >&2; exit 2; }
mkdir -p "$work"

debootstrap --variant=minbase bookworm "$root" http://deb.debian.org/debian > "$work/debootstrap.log"
cp /etc/resolv.conf "$root/etc/resolv.conf"
mount -t proc proc "$root/proc"
mount --bind /dev "$root/dev"
git clone -q "$repo" "$root/root/viscor"
# The README's main-job command, the line after its "Main job" heading's ```sh.
command=$(awk '/^```sh/ {getline; print; exit}' "$repo/README.md")
echo "$command" > "$root/root/main-job.sh"
echo "time_fresh_machine: running: $command"

start=$(date +%s)
chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
  bash -c 'cd /root/viscor && bash /root/main-job.sh' > "$work/main-job.log" 2>&1
end=$(date +%s)
built=$(stat -c %Y "$root/root/viscor/build/CMakeCache.txt")
echo "time_fresh_machine: packages $((built - start)) s, configure + build + first CoR $((end - built)) s," \
     "total $((end - start)) s (log: $work/main-job.log)"
tail -n 14 "$work/main-job.log"
