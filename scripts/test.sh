#!/usr/bin/env bash
# The test command of a fresh Debian bookworm machine: install what the tests need, then run
# every test of the workspace. Needs no Rust nightly: the SPIR-V is committed (assets/spirv/)
# and a stable test checks it against the shader sources' hash.
#
# Installs with apt (as root, or through sudo), each only if missing:
# - mesa-vulkan-drivers + libvulkan1 from bookworm-backports: Mesa 25's lavapipe, a CPU Vulkan
#   1.4 driver with acceleration structures, ray-tracing pipelines and ray queries (bookworm's
#   own Mesa 22 has no ray tracing), for every CPU ≡ Vulkan test;
# - vulkan-validationlayers: the Khronos validation layer every Vulkan test runs under;
# - spirv-tools: spirv-val over the committed SPIR-V;
# - chromium: the HTML report's screenshot and the WebGPU page's tests;
# - gcc, g++, libvulkan-dev: the C header check, the C sample, the Embree any-hit port.
# AOKIT_NO_INSTALL=1 skips the installation (a machine that already has everything).
#
# Fast tests first: the unit tests and the fast lane (contract staleness, exhaustive kernel
# tests, the validation layer's positive controls, …) run before the slow binaries; `--fast`
# runs only them. A test that cannot run (no Vulkan driver, no Chromium, no compiler) FAILS,
# unless AOKIT_ALLOW_SKIP names the need or the test (tests/common/skip.rs), e.g.
# `AOKIT_ALLOW_SKIP=vulkan,chromium`; the skipped tests are listed at the end. Under CI
# nothing may skip.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)

if [ "${AOKIT_NO_INSTALL:-0}" != 1 ]; then
  SUDO=""
  if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  packages=(vulkan-validationlayers spirv-tools chromium gcc g++ libvulkan-dev)
  backports=(mesa-vulkan-drivers libvulkan1)
  missing=()
  for p in "${packages[@]}" "${backports[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  # lavapipe must be Mesa 25 (ray tracing): an older one counts as missing.
  mesa=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || true)
  case "$mesa" in 2[5-9].*) ;; *) [[ " ${missing[*]} " == *" mesa-vulkan-drivers "* ]] || missing+=(mesa-vulkan-drivers) ;; esac
  if [ ${#missing[@]} -gt 0 ]; then
    echo "test.sh: installing ${missing[*]} (lavapipe + validation layers for the Vulkan tests, spirv-tools, chromium, C compilers)"
    sources() { find /etc/apt -maxdepth 2 \( -name '*.list' -o -name '*.sources' \) -type f; }
    if ! sources | xargs -r grep -qs bookworm-backports; then
      mirror=$(sources | xargs -r grep -hE '^(URIs:|deb )' \
        | grep -v -- '-security' | sed -E 's/^(URIs:|deb)[[:space:]]+(\[[^]]*\][[:space:]]+)?//' | awk '{print $1}' | grep -m1 debian || true)
      if [ -z "$mirror" ]; then echo "test.sh: no Debian mirror found in the apt sources to add bookworm-backports from" >&2; exit 1; fi
      echo "deb $mirror bookworm-backports main" | $SUDO tee /etc/apt/sources.list.d/aokit-backports.list >/dev/null
    fi
    $SUDO apt-get update -qq
    $SUDO apt-get install -y -qq -t bookworm-backports "${backports[@]}" >/dev/null
    $SUDO apt-get install -y -qq "${packages[@]}" >/dev/null
    echo "test.sh: apt done after $(( $(date +%s) - start )) s"
  fi
fi

if [ -n "${CI:-}" ] && [ -n "${AOKIT_ALLOW_SKIP:-}" ]; then
  echo "test.sh: AOKIT_ALLOW_SKIP is set under CI, where nothing may skip" >&2
  exit 1
fi
export AOKIT_SKIP_LOG="$PWD/target/aokit-skipped.log"
mkdir -p target
: >"$AOKIT_SKIP_LOG"
report_skips() {
  local n
  n=$(grep -c . "$AOKIT_SKIP_LOG" || true)
  if [ "$n" -gt 0 ]; then
    echo "test.sh: $n skipped:"
    sed 's/^/  /' "$AOKIT_SKIP_LOG"
  else
    echo "test.sh: 0 skipped"
  fi
}
trap report_skips EXIT

# Every cargo call below selects the whole workspace and picks its test targets by name. Cargo
# resolves the dependencies' features from the packages a call selects, so `-p aokit` and
# `--workspace --exclude aokit` compiled the shared dependencies twice, with two feature sets
# (8.7 minutes the second time on CI's 2 cores); one selection compiles them once.
#
# The integration tests of every workspace package, by name, as Cargo lists them.
mapfile -t all_tests < <(cargo metadata --format-version 1 --no-deps \
  | grep -o '"kind":\["test"\],"crate_types":\["bin"\],"name":"[^"]*"' | sed 's/.*"name":"//; s/"$//')
# The fast lane: seconds to a few minutes.
fast=(spirv_assets contract c_constants citations kernel_declarations technique_registry pass_graph
  kernel_math metrics sync_validation exhaustive)
for t in "${fast[@]}"; do
  if [[ " ${all_tests[*]} " != *" $t "* ]]; then
    echo "test.sh: the fast lane's test $t is not among the workspace's test targets (${#all_tests[@]} found)" >&2
    exit 1
  fi
done
lane_args() { for t in "$@"; do printf -- '--test\n%s\n' "$t"; done; }
mapfile -t fast_args < <(lane_args "${fast[@]}")
cargo test --workspace --lib --bins "${fast_args[@]}"
echo "test.sh: fast lane passed after $(( $(date +%s) - start )) s"
if [ "${1:-}" = "--fast" ]; then exit 0; fi

# The slow lane: every other test target of the workspace, the doc tests, the examples.
slow=()
for t in "${all_tests[@]}"; do
  [[ " ${fast[*]} " == *" $t "* ]] || slow+=("$t")
done
mapfile -t slow_args < <(lane_args "${slow[@]}")
cargo test --workspace --doc
cargo test --workspace --examples "${slow_args[@]}"
echo "test.sh: main workspace passed after $(( $(date +%s) - start )) s"
# The Bevy plugin: its own workspace, so Bevy stays out of the main one (docs/bevy.md). Bevy 0.20
# declares rust-version 1.97.1 and builds with older toolchains too, hence the flag.
cargo test --manifest-path aokit-bevy/Cargo.toml --ignore-rust-version
# Its example end to end, headless (it fails when no screenshot was written).
cargo run --manifest-path aokit-bevy/Cargo.toml --ignore-rust-version --example bevy_sponza -- \
  --scene cornell --size 160x96 --screenshot target/bevy_example_smoke.png
echo "test.sh: finished in $(( $(date +%s) - start )) s"
