// A fixture of tools/check_history.py (tests/CMakeLists.txt): lines marked BAD hold
// an issue number, the others only things that look like one; 8 BAD lines in the
// fixture's files, none counted in its docs/history.md.
#pragma once
#include <vector>  // a directive
#define VISCOR_FIXTURE_LEVEL 3
#if 0
#endif
// BAD: the creep after maximal compression (issue 18 item 8)
// BAD: see issues 12-14
// BAD: fixed in (#35)
// BAD: as PR 7 did
// Not: C++20, version 1.2.3, 2026-12-04, colours #1f77b4 and #ffffff, x#1, &#35;,
// an Issue tracker, issues of precision, tissue 5, the 3rd item.
