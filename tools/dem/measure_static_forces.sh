#!/usr/bin/env bash
# Prints the forces of tests/dem_static_force_data.hpp from the installed lmp and
# liggghts (Debian 12 packages lammps, liggghts): run from this directory.
set -euo pipefail
cd "$(dirname "$0")"
lmp_force() {  # contact model damp
  lmp -log none -var E 1e8 -var nu 0.3 -var damp "$3" -var model "$2" -in "static_force_lammps_$1.in" 2>/dev/null |
    grep '^FORCE' | awk '{print $2}'
}
lig_force() {  # contact e [wall_E]
  local extra=()
  [ "$1" = wall ] && extra=(-var Ew "$3" -var nuw 0.3)
  liggghts -log none -var E 1e8 -var nu 0.3 -var e "$2" "${extra[@]}" -in "static_force_liggghts_$1.in" 2>/dev/null |
    grep -a -A1 'Step' | tail -1 | awk '{print $2}'
}
for contact in pair wall; do
  echo "lammps velocity $contact 0.3 $(lmp_force $contact velocity 0.3)"
  echo "lammps mass_velocity $contact 1e4 $(lmp_force $contact mass_velocity 1e4)"
  echo "lammps viscoelastic $contact 3e8 $(lmp_force $contact viscoelastic 3e8)"
  echo "lammps tsuji $contact 0.3 $(lmp_force $contact tsuji 0.3)"
done
echo "liggghts hertz pair 0.5 $(lig_force pair 0.5)"
echo "liggghts hertz wall 0.5 (wall E 1e8) $(lig_force wall 0.5 1e8)"
echo "liggghts hertz wall 0.5 (wall E 1e30) $(lig_force wall 0.5 1e30)"
