#!/bin/sh
# OPTIONS.md is exactly what `avc options --markdown` prints: the options reference is generated
# from the option tables and cannot drift from them.
# Usage: options_reference_test.sh AVC OPTIONS_MD
set -eu
if ! "$1" options --markdown | diff -u "$2" -; then
  echo "OPTIONS.md is out of date: build/bin/avc options --markdown > OPTIONS.md" >&2
  exit 1
fi
