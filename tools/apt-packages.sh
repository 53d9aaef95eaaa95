#!/bin/sh
# System packages the test suite needs beyond the language toolchains the
# machine has: clang with its sanitizer and libFuzzer runtimes, for the C
# decoder's sanitizer tests and fuzz smoke runs, tshark, which dissects
# captures with the generated Wireshark dissector (tests/test_wireshark.py),
# chromium, which renders the HTML reports headless to check what a reader
# sees (tests/test_report_pages.py), Frama-C with Why3, z3 and cvc4,
# which prove units of the generated C library (tools/prove.py), and the
# Arm toolchain with newlib and QEMU, which build the on-target testee and
# run it on an emulated Cortex-M4 (conformance/testees/c-target).
# Pinned to Debian 12's versions; each is skipped when it is already there.
set -eu
CLANG="clang-14=1:14.0.6-12 libclang-rt-14-dev=1:14.0.6-12"
TSHARK="tshark=4.0.17-0+deb12u3"
# Frama-C's WP and the provers it reaches through Why3 (tools/prove.py, `make prove`)
PROVERS="frama-c-base=20220511-manganese-3+b4 why3=1.5.1-1+b2 z3=4.8.12-3.1 cvc4=1.8-3"
# The Arm cross compiler and its C library, and QEMU's Arm system emulator
ARM="gcc-arm-none-eabi=15:12.2.rel1-1 libnewlib-arm-none-eabi=3.3.0-1.3+deb12u1"
# QEMU, like chromium below, is rebuilt by Debian's point releases and
# security updates, and only the newest build stays in the archive: the pin
# is the release's 7.2 stream.
QEMU_STREAM="1:7.2+dfsg-7+deb12u*"
# Debian's security archive keeps only the newest chromium build of a
# release, and replaces it every few weeks: an exact pin stops installing on
# the day the next build lands (156.0.8078.108 went that way). The pin is the
# build stream; when the archive has moved past it, the release's current
# build is installed and said so (the tests that use chromium check what a
# page shows, not a browser version).
CHROMIUM_STREAM="156.0.8078.*"
PACKAGES=""
if ! command -v clang-14 >/dev/null 2>&1 || [ ! -e /usr/lib/llvm-14/lib/clang/14.0.6/lib/linux/libclang_rt.fuzzer-x86_64.a ]; then
    PACKAGES="$CLANG"
fi
if ! command -v tshark >/dev/null 2>&1; then
    PACKAGES="$PACKAGES $TSHARK"
fi
if ! command -v frama-c >/dev/null 2>&1 || ! command -v why3 >/dev/null 2>&1 || ! command -v z3 >/dev/null 2>&1 \
        || ! command -v cvc4 >/dev/null 2>&1; then
    PACKAGES="$PACKAGES $PROVERS"
fi
if ! command -v arm-none-eabi-gcc >/dev/null 2>&1 || [ ! -e /usr/lib/arm-none-eabi/lib/libc.a ]; then
    PACKAGES="$PACKAGES $ARM"
fi
if ! command -v qemu-system-arm >/dev/null 2>&1; then
    PACKAGES="$PACKAGES qemu-system-arm=$QEMU_STREAM"
fi
if ! command -v chromium >/dev/null 2>&1; then
    PACKAGES="$PACKAGES chromium"
fi
if [ -z "${PACKAGES# }" ]; then
    exit 0
fi
SUDO=""
if [ "$(id -u)" != 0 ]; then
    if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
        echo "apt-packages: need root (or sudo) to install: $PACKAGES" >&2; exit 1
    fi
fi
$SUDO apt-get update -qq
case "$PACKAGES" in
    *tshark*)
        # wireshark-common's postinst asks whether non-root users may capture;
        # the tests only read files, so answer no before apt can ask.
        echo "wireshark-common wireshark-common/install-setuid boolean false" | $SUDO debconf-set-selections
        ;;
esac
case " $PACKAGES " in
    *" chromium "*)
        if apt-cache madison chromium | awk '{print $3}' | grep -q "^${CHROMIUM_STREAM%\*}"; then
            PACKAGES=$(echo "$PACKAGES" | sed "s/ chromium\b/ chromium=$CHROMIUM_STREAM/")
        else
            echo "apt-packages: chromium $CHROMIUM_STREAM is no longer in the archive; installing its current build" >&2
        fi
        ;;
esac
set -f  # the chromium and QEMU pins are patterns for apt, not for the shell
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $PACKAGES >/dev/null
