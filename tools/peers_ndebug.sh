#!/usr/bin/env bash
# Builds Box2D 2.4.1 and Chipmunk 7.0.3 from Debian's own source packages twice, with Debian's
# compiler flags (dpkg-buildflags, as their debian/rules use them): once as Debian ships them (no
# NDEBUG: Box2D's b2Assert and Chipmunk's cpAssertSoft/cpAssertWarn run) and once with -DNDEBUG.
# bench/assertion_cost runs the same peer workloads against both (LD_LIBRARY_PATH) to measure what
# the assertions cost. Nothing is installed: the libraries land in build-peers/{asserting,ndebug}/.
# Needs dpkg-dev (dpkg-source, dpkg-buildflags), cmake and a compiler; downloads the sources with a
# private deb-src list, leaving the system's apt configuration alone.
#
# Usage: tools/peers_ndebug.sh     (prints the two library directories)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$root/build-peers"
mkdir -p "$out/apt/lists/partial" "$out/src"

if ! command -v dpkg-source >/dev/null || ! command -v dpkg-buildflags >/dev/null; then
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends dpkg-dev >/dev/null
fi

# The source packages, from the archive the machine already uses.
suite="$(. /etc/os-release && echo "$VERSION_CODENAME")"
cat >"$out/apt/sources.list" <<LIST
deb-src http://deb.debian.org/debian $suite main
LIST
apt_opts=(-o "Dir::Etc::sourcelist=$out/apt/sources.list" -o "Dir::Etc::sourceparts=-"
  -o "Dir::State::Lists=$out/apt/lists" -o "APT::Sandbox::User=root")
cd "$out/src"
if ! ls box2d_*.dsc chipmunk_*.dsc >/dev/null 2>&1; then
  apt-get "${apt_opts[@]}" update -qq
  apt-get "${apt_opts[@]}" source --download-only -qq box2d chipmunk
fi
[ -d box2d ] || dpkg-source -x --skip-debianization box2d_*.dsc box2d >/dev/null
[ -d chipmunk ] || dpkg-source -x chipmunk_*.dsc chipmunk >/dev/null

build() {  # name, flags variant, extra cmake args...
  local name=$1 variant=$2
  shift 2
  local flags hardening=""
  [ "$name" = chipmunk ] && hardening="hardening=+all"  # as its debian/rules asks
  flags="$(DEB_BUILD_MAINT_OPTIONS=$hardening dpkg-buildflags --get CFLAGS)"
  local cxxflags
  cxxflags="$(DEB_BUILD_MAINT_OPTIONS=$hardening dpkg-buildflags --get CXXFLAGS)"
  local ldflags
  ldflags="$(DEB_BUILD_MAINT_OPTIONS=$hardening dpkg-buildflags --get LDFLAGS)"
  [ "$variant" = ndebug ] && flags="$flags -DNDEBUG" && cxxflags="$cxxflags -DNDEBUG"
  local dir="$out/$variant/build-$name"
  CFLAGS="$flags" CXXFLAGS="$cxxflags" LDFLAGS="$ldflags" \
    cmake -S "$out/src/$name" -B "$dir" -DCMAKE_BUILD_TYPE=None "$@" >/dev/null
  cmake --build "$dir" -j2 >/dev/null
  mkdir -p "$out/$variant/lib"
  find "$dir" -name "lib$name.so*" -exec cp -P {} "$out/$variant/lib/" \;
}
for variant in asserting ndebug; do
  [ -e "$out/$variant/lib/libbox2d.so.2" ] || build box2d "$variant" -DBUILD_SHARED_LIBS=ON \
    -DBOX2D_BUILD_TESTBED=OFF -DBOX2D_BUILD_UNIT_TESTS=OFF -DBOX2D_BUILD_DOCS=OFF
  [ -e "$out/$variant/lib/libchipmunk.so.7" ] || build chipmunk "$variant" -DBUILD_DEMOS=OFF -DBUILD_STATIC=OFF
done
echo "$out/asserting/lib"
echo "$out/ndebug/lib"
