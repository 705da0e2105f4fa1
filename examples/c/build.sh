#!/usr/bin/env bash
# Builds examples/c/build/aokit-c-sample from aokit_c_sample.c: C11, the system's Vulkan headers
# and loader (Debian: libvulkan-dev) and aokit's generated header (assets/include/aokit.h).
# Works from any directory; CC overrides the compiler (default cc).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
cc="${CC:-cc}"
if ! command -v "$cc" >/dev/null 2>&1; then
  echo "build.sh: no C compiler '$cc' (Debian: apt-get install gcc)" >&2
  exit 1
fi
if ! echo '#include <vulkan/vulkan.h>' | "$cc" -std=c11 -E -x c - >/dev/null 2>&1; then
  echo "build.sh: <vulkan/vulkan.h> not found (Debian: apt-get install libvulkan-dev)" >&2
  exit 1
fi
mkdir -p "$here/build"
"$cc" -std=c11 -Wall -Wextra -Werror -O2 -I "$root/assets/include" \
  -o "$here/build/aokit-c-sample" "$here/aokit_c_sample.c" -lvulkan -lm
