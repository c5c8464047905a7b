#!/bin/bash
# Runs the commands of a README section's first ```sh block exactly as written, one line at a
# time, from a folder laid out like the repository (build/ and ../shared linked in), so commands
# that write into the working folder write into a temporary one.
# Usage: readme_block_test.sh README "## Section" BUILD_DIR SHARED_DIR [PATH_TO_CLEAR...]
set -euo pipefail
readme=$1
section=$2
build=$3
shared=$4
shift 4

block=$(awk -v section="$section" '
  $0 == section { in_section = 1; next }
  in_section && /^## / { exit }
  in_section && /^```sh/ { in_block = 1; next }
  in_block && /^```/ { exit }
  in_block { print }' "$readme")
if [ -z "$block" ]; then
  echo "no \`\`\`sh block under '$section' in $readme" >&2
  exit 1
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/repo"
ln -s "$build" "$work/repo/build"
ln -s "$shared" "$work/shared"
# Absolute paths the commands write to, cleared so a second run starts as the first did.
for path in "$@"; do rm -rf "$path"; done

cd "$work/repo"
while IFS= read -r line; do
  [ -z "$line" ] && continue
  echo "+ $line"
  if ! bash -c "$line"; then
    echo "README command failed: $line" >&2
    exit 1
  fi
done <<< "$block"
for path in "$@"; do rm -rf "$path"; done
