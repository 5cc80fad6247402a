#!/usr/bin/env python3
# BAD: issue #42 in a comment
print("see #42")  # BAD: in a string
print(f"{len(sys.argv)}")  # not
