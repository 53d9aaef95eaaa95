#!/bin/sh
# System packages the test suite needs beyond the language toolchains the
# machine has: clang with its sanitizer and libFuzzer runtimes, for the C
# decoder's sanitizer tests and fuzz smoke runs. Pinned to Debian 12's
# versions; skipped when they are already installed.
set -eu
PACKAGES="clang-14=1:14.0.6-12 libclang-rt-14-dev=1:14.0.6-12"
if command -v clang-14 >/dev/null 2>&1 && [ -e /usr/lib/llvm-14/lib/clang/14.0.6/lib/linux/libclang_rt.fuzzer-x86_64.a ]; then
    exit 0
fi
SUDO=""
if [ "$(id -u)" != 0 ]; then
    if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
        echo "apt-packages: need root (or sudo) to install: $PACKAGES" >&2; exit 1
    fi
fi
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $PACKAGES >/dev/null
