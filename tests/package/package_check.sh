#!/usr/bin/env bash
# The Debian package, built and used as a user would (cmake/Package.cmake):
#   1. `cpack -G DEB` in the build folder BUILD writes gdpn_VERSION_ARCH.deb into WORK;
#   2. it is unpacked into an empty prefix (dpkg-deb -x) and every file named by the issue is
#      there: the program, the Python module, parts, examples, guides, man page, desktop entry,
#      icon, MIME type;
#   3. readelf: no RUNPATH or RPATH of its programs and libraries points into the build or
#      source tree;
#   4. from /, under `env -i` with only the prefix on the paths: `gdpn --version`, `gdpn check`
#      of the packaged sorting station (built from parts: they must come from the package),
#      `gdpn parts belt_conveyor` (its file in the package) and `python3 -c "import gdpn"`
#      (the packaged module, which loads and checks a model);
#   5. `apt-get install --simulate` of the .deb: its dependencies resolve on this machine.
# Usage: package_check.sh BUILD SOURCE WORK [CPACK]
set -euo pipefail
build=$(realpath "$1")
source=$(realpath "$2")
work=$3
cpack=${4:-cpack}
rm -rf "$work"
mkdir -p "$work"
work=$(realpath "$work")
fail() { echo "package_check: error: $*" >&2; exit 1; }

# 1. the package
(cd "$build" && "$cpack" -G DEB -B "$work/cpack" >"$work/cpack.log" 2>&1) || { cat "$work/cpack.log" >&2; fail "cpack failed"; }
debs=("$work"/cpack/gdpn_*.deb)
[[ ${#debs[@]} -eq 1 && -f ${debs[0]} ]] || fail "cpack wrote no gdpn_*.deb into $work/cpack"
deb=${debs[0]}
echo "built $(basename "$deb") ($(($(stat -c %s "$deb") / 1024 / 1024)) MiB)"
depends=$(dpkg-deb --field "$deb" Depends)
grep -q "python3" <<<"$depends" || fail "the package declares no dependency on python3"
grep -q "libode" <<<"$depends" || fail "dpkg-shlibdeps found no libraries (no libode among the dependencies)"

# 2. unpacked into an empty prefix
root=$work/root
dpkg-deb -x "$deb" "$root"
usr=$root/usr
for f in bin/gdpn lib/python3/dist-packages/gdpn.cpython-*.so share/gdpn/parts/conveyors/belt_conveyor.gdpn.yaml \
  share/gdpn/examples/station/sorting_station.gdpn.yaml share/doc/gdpn/cli.md share/doc/gdpn/python.md \
  share/man/man1/gdpn.1.gz share/applications/gdpn.desktop share/icons/hicolor/scalable/apps/gdpn.svg \
  share/mime/packages/gdpn.xml; do
  compgen -G "$usr/$f" >/dev/null || fail "the package holds no /usr/$f"
done
grep -q '^Exec=gdpn ide %f$' "$usr/share/applications/gdpn.desktop" || fail "the desktop entry does not open gdpn ide with a file"
grep -q 'glob pattern="\*.gdpn.yaml"' "$usr/share/mime/packages/gdpn.xml" || fail "the MIME type does not match *.gdpn.yaml"
if command -v desktop-file-validate >/dev/null; then desktop-file-validate "$usr/share/applications/gdpn.desktop"; fi
man_page=$(zcat "$usr/share/man/man1/gdpn.1.gz")
grep -q '^\.SS "gdpn analyze' <<<"$man_page" || fail "the man page has no section on gdpn analyze"

# 3. no RUNPATH into the build or source tree
elves=0
while IFS= read -r -d '' f; do
  head -c 4 "$f" | grep -q $'\x7fELF' || continue
  elves=$((elves + 1))
  paths=$(readelf -d "$f" | grep -E 'RUNPATH|RPATH' || true)
  if [[ -n $paths ]]; then
    grep -qF -e "$build" -e "$source" <<<"$paths" && fail "$f: $paths (into the build or source tree)"
    echo "note: $f: $paths"
  fi
done < <(find "$root" -type f -print0)
((elves >= 2)) || fail "found $elves ELF files in the package (the program and the module at least)"
echo "$elves ELF files, none with a RUNPATH into the build or source tree"

# 4. from /, with only the prefix on the paths
home=$work/home
mkdir -p "$home"
run() {
  (cd / && env -i HOME="$home" PATH="$usr/bin:/usr/bin:/bin" XDG_DATA_DIRS="$usr/share" \
    PYTHONPATH="$(echo "$usr"/lib/python3/dist-packages)" "$@")
}
version=$(run gdpn --version)
[[ $version == "gdpn "* ]] || fail "gdpn --version said '$version'"
[[ $(run sh -c 'command -v gdpn') == "$usr/bin/gdpn" ]] || fail "gdpn on the PATH is not the package's"
run gdpn check "$usr/share/gdpn/examples/station" || fail "gdpn check of the packaged sorting station failed"
part=$(run gdpn parts belt_conveyor | sed -n 2p | tr -d ' ')
[[ $part == "$usr/share/gdpn/parts/"* ]] || fail "gdpn parts belt_conveyor found it at '$part', not in the package"
run /usr/bin/python3 -c "
import gdpn, sys
assert gdpn.__file__.startswith('$usr/'), gdpn.__file__
m = gdpn.load('$usr/share/gdpn/examples/basics/producer_consumer')
r = m.run(until=10)
assert r['time'] == 10, r['time']
print('import gdpn:', gdpn.__file__, 'version', gdpn.__version__)
" || fail "python3 -c 'import gdpn' from the package failed"
echo "$version from the package: --version, check, parts and import gdpn work from / under env -i"

# 5. its dependencies resolve
command -v apt-get >/dev/null || fail "no apt-get on this machine"
apt-get -o DPkg::Lock::Timeout=300 install --simulate "$deb" >"$work/apt.log" 2>&1 || { cat "$work/apt.log" >&2; fail "apt-get install --simulate failed"; }
echo "apt-get install --simulate: installs $(grep -E '^Inst ' "$work/apt.log" | awk '{print $2}' | paste -sd ' ')"
