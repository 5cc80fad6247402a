#!/usr/bin/env bash
# Not: shell counts and lengths.
echo "$# ${#args[@]} $#"
