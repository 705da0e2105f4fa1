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

cargo test --workspace
echo "test.sh: finished in $(( $(date +%s) - start )) s"
