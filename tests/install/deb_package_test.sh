#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `cpack -G DEB` makes a package that holds the executable and its data folder and depends on
# what flange runs; the unpacked package finds its data beside itself.
#   bash tests/install/deb_package_test.sh BUILD_DIR VERSION
set -euo pipefail

build="$(cd "$1" && pwd)"
version="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() {
  echo "deb test: $*" >&2
  echo "  reproduce: cd $build && cpack -G DEB && dpkg-deb -I flange_*.deb && dpkg-deb -c flange_*.deb" >&2
  exit 1
}

cpack -G DEB -B "$work" --config "$build/CPackConfig.cmake" >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log" >&2; fail "cpack failed"; }
debs=("$work"/flange_*.deb)
[ "${#debs[@]}" -eq 1 ] && [ -f "${debs[0]}" ] || fail "expected one flange_*.deb, got ${debs[*]}"
deb="${debs[0]}"
echo "deb test: $(basename "$deb"), $(du -k "$deb" | cut -f1) KiB"

info="$(dpkg-deb -I "$deb")"
depends="$(sed -n 's/^ Depends: //p' <<<"$info")"
echo "deb test: Depends: $depends"
grep -qx " Package: flange" <<<"$info" || fail "Package is not flange"
grep -qx " Version: $version" <<<"$info" || fail "Version is not $version"
# What flange runs, and (from dpkg-shlibdeps) the shared libraries it links.
for package in verilator 'g\+\+' make zlib1g-dev libfmt-dev libcli11-dev yosys gnuplot-nox \
  libc6 'libfmt[0-9]+' 'libstdc\+\+6'; do
  grep -Eq "(^|, |\| )$package( \(|,|$| \|)" <<<"$depends" || fail "Depends lacks $package"
done

files="$(dpkg-deb -c "$deb" | awk '{print $1, $6}')"
for file in usr/bin/flange \
  usr/share/flange/rtl/iir_core.sv usr/share/flange/rtl/iir_mac.sv \
  usr/share/flange/rtl/lint/waivers.vlt usr/share/flange/rtl/syn/synth_xc7.sh \
  usr/share/flange/rtl/board/basys3_top.sv usr/share/flange/rtl/board/basys3.xdc \
  usr/share/flange/rtl/board/vivado_build.tcl \
  usr/share/flange/coeffs/measurement_sos/filter.json \
  usr/share/flange/coeffs/measurement_df1/coeffs.mem \
  usr/share/flange/coeffs/vehicle_sos/iir_coeffs_pkg.sv \
  usr/share/flange/tb/cosim_main.cpp usr/share/flange/tb/iir_core_dut.cpp \
  usr/share/flange/model/filter_json.h \
  usr/share/flange/lib/libflange_tb.a usr/share/flange/lib/libflange_model.a; do
  grep -q " \./$file$" <<<"$files" || fail "the package lacks /$file"
done
for file in usr/bin/flange usr/share/flange/rtl/syn/synth_xc7.sh; do
  grep -Eq "^-rwx.* \./$file$" <<<"$files" || fail "/$file is not executable"
done
stray="$(awk '{print $2}' <<<"$files" |
  grep -Ev '^\./(usr/(bin/flange|share/flange/.*|share/doc/flange/.*))?$' |
  grep -Ev '^\./usr/(bin|share|share/doc)?/?$' || true)"
[ -z "$stray" ] || fail "files outside /usr/bin/flange and /usr/share/flange: $stray"

dpkg-deb -x "$deb" "$work/root"
# Stripping the package must leave the runner's archives linkable.
for archive in libflange_tb.a libflange_model.a; do
  [ -n "$(nm -g --defined-only "$work/root/usr/share/flange/lib/$archive" 2>/dev/null)" ] ||
    fail "/usr/share/flange/lib/$archive has no symbols left"
done
FLANGE_NO_SOURCE_TREE=1 "$work/root/usr/bin/flange" --version >"$work/version.txt" ||
  fail "the unpacked flange --version failed"
grep -qx "flange $version" "$work/version.txt" || fail "--version does not say flange $version"
grep -qx "data: $work/root/usr/share/flange (installed)" "$work/version.txt" ||
  fail "the unpacked flange does not find its data folder: $(cat "$work/version.txt")"
echo "deb test: files, Depends and the unpacked flange's data folder as expected"
