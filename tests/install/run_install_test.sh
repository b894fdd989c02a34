#!/usr/bin/env bash
# molsurf as its users install it (the ctest `install`), in a temporary folder outside the
# source tree: `cmake --install` of the build into a prefix (the command, the library, the
# headers, the CMake package), a program built against that prefix by find_package alone
# (tests/install/consumer) and run, then `pip install --no-build-isolation` of the source
# tree into a venv, reusing the build (MOLSURF_BUILD_DIR), and the pytest suite
# python/tests run against the installed module.
# Usage: run_install_test.sh SOURCE_DIR BUILD_DIR VERSION [PYTHON]
# Without PYTHON (the build has no Python module or no pytest) the Python half is skipped.
set -euo pipefail
src=$(cd "$1" && pwd)
build=$(cd "$2" && pwd)
version=$3
python=${4:-}

work=$(mktemp -d "${TMPDIR:-/tmp}/molsurf-install.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work"
unset PYTHONPATH MOLSURF_BUILD_DIR
fail() { echo "FAIL: $*" >&2; exit 1; }
step() { echo "== ${SECONDS}s: $*"; }

step "cmake --install $build --prefix $work/prefix"
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null
# The library folder is GNUInstallDirs' (lib, or lib/<multiarch> for the prefix /usr).
libdir=$(cd "$prefix" && find . -name libmolsurf.a -printf '%h\n' | sed 's|^\./||')
[[ -n $libdir ]] || fail "not installed: libmolsurf.a"
for f in bin/molsurf "$libdir"/cmake/molsurf/molsurfConfig.cmake "$libdir"/cmake/molsurf/molsurfConfigVersion.cmake \
         "$libdir"/cmake/molsurf/molsurfTargets.cmake; do
  [[ -f $prefix/$f ]] || fail "not installed: $f"
done
# Every public header, and nothing of theirs from outside include/molsurf (src/ is not installed).
diff <(cd "$src/include/molsurf" && ls ./*.hpp) <(cd "$prefix/include/molsurf" && ls ./*.hpp) ||
  fail "installed headers differ from include/molsurf"
if grep -n '#include "' "$prefix"/include/molsurf/*.hpp | grep -v '#include "molsurf/'; then
  fail "a public header includes a header that is not installed"
fi
[[ $("$prefix/bin/molsurf" --version) == "molsurf $version" ]] || fail "molsurf --version: $("$prefix/bin/molsurf" --version)"

step "find_package(molsurf) consumer"
cmake -S "$src/tests/install/consumer" -B consumer -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$prefix" >consumer.log || { cat consumer.log; fail "consumer: configure"; }
grep -qx "molsurf_DIR:PATH=$prefix/$libdir/cmake/molsurf" consumer/CMakeCache.txt ||
  fail "the consumer found another molsurf: $(grep molsurf_DIR consumer/CMakeCache.txt)"
cmake --build consumer >>consumer.log || { cat consumer.log; fail "consumer: build"; }
read -r consumer_version consumer_area consumer_faces < <(consumer/consumer "$src/data/pdb/1crn.pdb" 1crn.vtp)
echo "consumer: molsurf $consumer_version, 1crn area $consumer_area, $consumer_faces faces"
[[ $consumer_version == "$version" ]] || fail "consumer's MOLSURF_VERSION $consumer_version"
((consumer_faces > 1000)) || fail "consumer's surface has $consumer_faces faces"
"$prefix/bin/molsurf" check 1crn.vtp >/dev/null || fail "the consumer's surface fails molsurf check"

if [[ -z $python ]]; then
  echo "== Python: skipped (the build has no Python module or no pytest)"
  exit 0
fi

step "pip install --no-build-isolation $src (MOLSURF_BUILD_DIR=$build)"
# Debian's pip (python3-pip, seen through --system-site-packages) installs into the venv
# that runs it: the same pip as the venv's own, without the seconds ensurepip takes.
"$python" -m venv --system-site-packages --without-pip venv
MOLSURF_BUILD_DIR=$build venv/bin/python -m pip install -q --no-build-isolation --no-index \
  --disable-pip-version-check "$src"
# The module from the venv, its version the project's everywhere, the library's numbers.
venv/bin/python - "$work/venv" "$version" "$src/data/pdb/1crn.pdb" "$consumer_area" <<'PY'
import importlib.metadata, pathlib, sys
import molsurf
venv, version, crambin, consumer_area = sys.argv[1:]
where = pathlib.Path(molsurf.__file__).resolve()
assert where.is_relative_to(pathlib.Path(venv).resolve()), f"molsurf imported from {where}"
assert molsurf.__version__ == version, molsurf.__version__
assert importlib.metadata.version("molsurf") == version, importlib.metadata.version("molsurf")
area = molsurf.areas(crambin).area
assert area == float(consumer_area), (area, consumer_area)
print(f"module: {where.name} {molsurf.__version__}, 1crn area {area!r}")
PY

step "pytest $src/python/tests against the installed module"
MOLSURF_SOURCE_DIR=$src MOLSURF_CLI=$prefix/bin/molsurf MPLBACKEND=Agg PYTHONDONTWRITEBYTECODE=1 \
  venv/bin/python -m pytest -q -p no:cacheprovider "$src/python/tests"
step "done"
