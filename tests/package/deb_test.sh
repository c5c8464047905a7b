#!/usr/bin/env bash
# The Debian package (README, Lab deployment): `scripts/package` as the README writes it, then the
# .deb installed with dpkg into an empty root (not this machine's), and its avc run from there.
# Checks: the files a lab host needs are in it; `avc version` and `avc demo --help` run from the
# installed copy; `avc spy` finds the installed types jar; every shared library the binary loads
# directly belongs to a package the .deb depends on (so apt on a clean host installs them all); and, when
# apt has package lists, apt resolves the .deb's dependencies.
#   deb_test.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
source_dir=$1
build_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cd "$source_dir"
scripts/package "$build_dir" | tee "$work/package.log"
deb=$(sed -n 's/^package: //p' "$work/package.log")
[ -f "$deb" ] || fail "scripts/package named no .deb ($deb)"
case "$(basename "$deb")" in
  avc_*_amd64.deb) ;;
  *) fail "unexpected package file name $(basename "$deb")" ;;
esac

# Install into an empty root: dpkg needs only its database there.
root="$work/root"
mkdir -p "$root/var/lib/dpkg/info" "$root/var/lib/dpkg/updates"
touch "$root/var/lib/dpkg/status"
dpkg --root="$root" --force-depends --log=/dev/null -i "$deb" >"$work/dpkg.log" 2>&1 ||
  { cat "$work/dpkg.log"; fail "dpkg -i into an empty root failed"; }
dpkg --root="$root" -s avc | grep -q "^Status: install ok installed" ||
  fail "dpkg does not list avc as installed in the root"

for file in usr/bin/avc usr/share/avc/avc-lcmtypes.jar usr/share/avc/launch/lab-three-hosts.toml \
    usr/sbin/avc-setup-lab-host usr/lib/systemd/system/avc-up@.service; do
  [ -e "$root/$file" ] || fail "the package has no /$file"
done
grep -q "^ExecStart=avc up " "$root/usr/lib/systemd/system/avc-up@.service" ||
  fail "the unit's ExecStart does not run avc up"

avc="$root/usr/bin/avc"
"$avc" version | tee "$work/version.log"
grep -q "avc" "$work/version.log" || fail "avc version printed nothing recognisable"
"$avc" demo --help >"$work/demo-help.log" || fail "avc demo --help failed from the package"
grep -q -- "--plant" "$work/demo-help.log" || fail "avc demo --help lists no --plant"
"$avc" spy --dry-run >"$work/spy.log" 2>&1 || { cat "$work/spy.log"; fail "avc spy --dry-run failed"; }
grep -qF "$root/usr/bin/../share/avc/avc-lcmtypes.jar" "$work/spy.log" ||
  grep -qF "$root/usr/share/avc/avc-lcmtypes.jar" "$work/spy.log" ||
  { cat "$work/spy.log"; fail "avc spy does not use the installed jar"; }

# Every library the binary links directly (its NEEDED entries: what dpkg-shlibdeps reads) comes
# from a package in Depends; the libraries those load are their packages' own dependencies.
depends=$(dpkg-deb --field "$deb" Depends)
echo "Depends: $depends"
# The package that installed a library path, trying it as written and resolved, with and without
# /usr (bookworm merges /lib into /usr/lib, and dpkg knows each file under one of the two).
owner_of() {
  local path candidate
  for path in "$1" "$(readlink -f "$1")"; do
    for candidate in "$path" "${path#/usr}" "/usr$path"; do
      dpkg -S "$candidate" 2>/dev/null | head -n 1 | cut -d: -f1 && return 0
    done
  done
  return 1
}
readelf -d "$avc" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p' > "$work/needed"
[ -s "$work/needed" ] || fail "the binary lists no shared libraries"
ldd "$avc" > "$work/ldd"
# Depends entries look like "libfoo1 (>= 1.2), libbar2 | libbaz": one package name per line.
echo "$depends" | tr ',|' '\n\n' | sed 's/(.*//; s/[[:space:]]//g' | grep -v '^$' > "$work/depends"
missing=""
while read -r soname; do
  # "libfoo.so.1 => /path (addr)", or for the dynamic loader "/path/ld-linux-x86-64.so.2 (addr)".
  lib=$(awk -v name="$soname" '$1 == name && $2 == "=>" {print $3}
      $1 ~ ("/" name "$") {print $1}' "$work/ldd" | head -n 1)
  [ -n "$lib" ] || fail "ldd cannot resolve $soname"
  owner=$(owner_of "$lib") || fail "no Debian package owns $lib"
  # The owner itself, or a virtual package it provides ("liblapack3 | liblapack.so.3" is met by
  # whichever LAPACK the alternatives chose, e.g. libatlas3-base).
  provided=$(dpkg-query -W -f='${Provides}' "$owner" 2>/dev/null | tr ',' '\n' |
             sed 's/(.*//; s/[[:space:]]//g' | grep -v '^$' || true)
  if ! printf '%s\n%s\n' "$owner" "$provided" | grep -qxFf "$work/depends"; then
    missing="$missing $owner($soname)"
  fi
done < "$work/needed"
[ -z "$missing" ] || fail "libraries from packages the .deb does not depend on:$missing"
echo "all $(wc -l < "$work/needed") libraries the binary links come from declared dependencies"

if compgen -G "/var/lib/apt/lists/*_Packages*" >/dev/null; then
  apt-get install --simulate -qq "$deb" >"$work/apt.log" 2>&1 ||
    { cat "$work/apt.log"; fail "apt cannot resolve the package's dependencies"; }
  echo "apt resolves the package's dependencies"
else
  echo "no apt package lists here: dependency resolution by apt not checked"
fi
echo "package: $(basename "$deb") installs and runs"
