// Stubs for the parts of Onboard-SDK 3.3.x that the OPEN protocol does not
// need: the Linux platform (serial port and thread handle, declared in
// platform33/ because 3.3's Protocol constructs them itself), the log, the
// frame trace and the few Vehicle members the broadcast unpacker asks.
// Everything here is ours; the SDK's own files are compiled unchanged beside
// it (osdk_conformance/sdk/families/protocol.py lists them).
//
// What a stub does, and why:
//  - the serial device reads the bytes the adapter queued (one read per
//    chunk, as a UART driver returns them), sends into a capture buffer, and
//    its clock stands still: session timeouts are never reached in one
//    request. When the bytes are used up it throws okit_sdk::Drained, since
//    Protocol::receive() polls until it has a frame;
//  - locks do nothing: the testee runs one thread;
//  - the log writes to stderr, never stdout (stdout carries the JSON answers);
//  - printFrame, the SDK's frame trace, passes a received frame's header to
//    the adapter and writes nothing;
//  - Vehicle answers only which aircraft it is, which selects the SDK's own
//    broadcast unpacker; a member the operations never reach aborts loudly.
#include "adapter.h"

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>

using namespace DJI;
using namespace DJI::OSDK;

namespace okit_sdk {

VehicleKind g_vehicle = VEHICLE_M100_FW31;

[[noreturn]] void not_reached(const char *what)
{
    std::fprintf(stderr, "sdk testee: stub %s reached; the claimed operations never call it\n", what);
    std::abort();
}

} // namespace okit_sdk

namespace DJI {
namespace OSDK {

// ---- the serial device ------------------------------------------------------------------
LinuxSerialDevice::LinuxSerialDevice(const char *, uint32_t)
    : next_chunk(0), taken_of_chunk(0), pos(0), last_base(0)
{
}
LinuxSerialDevice::~LinuxSerialDevice() {}
void LinuxSerialDevice::init() {}
time_ms LinuxSerialDevice::getTimeStamp() { return 0; }
size_t LinuxSerialDevice::send(const uint8_t *data, size_t len)
{
    sent.insert(sent.end(), data, data + len);
    return len;
}
size_t LinuxSerialDevice::readall(uint8_t *out, size_t maxlen)
{
    okit_sdk::before_read(this);
    while (next_chunk < chunks.size()) {
        size_t want = chunks[next_chunk] - taken_of_chunk;
        if (want == 0) {
            next_chunk++;
            taken_of_chunk = 0;
            continue;
        }
        if (want > maxlen) want = maxlen;
        std::memcpy(out, input.data() + pos, want);
        last_base = pos;
        pos += want;
        taken_of_chunk += want;
        if (taken_of_chunk == chunks[next_chunk]) {
            next_chunk++;
            taken_of_chunk = 0;
        }
        return want;
    }
    throw okit_sdk::Drained();
}
bool LinuxSerialDevice::drained() const { return next_chunk >= chunks.size(); }

// ---- the thread handle: one thread, nothing to lock ---------------------------------------
void PosixThreadManager::init() {}
void PosixThreadManager::lockMemory() {}
void PosixThreadManager::freeMemory() {}
void PosixThreadManager::lockMSG() {}
void PosixThreadManager::freeMSG() {}
void PosixThreadManager::lockACK() {}
void PosixThreadManager::freeACK() {}
void PosixThreadManager::notify() {}
void PosixThreadManager::wait(int) {}

// ---- the frame trace: received frames to the adapter --------------------------------------
void printFrame(HardDriver *, Header *header, bool toAircraft)
{
    if (!toAircraft) okit_sdk::trace_frame(header);
}

// ---- log: to stderr ----------------------------------------------------------------------
Log::Log(Mutex *m) : mutex(m), vaild(true) {}
Log::~Log() {}
Log &Log::title(int level, const char *prefix, const char *func, int line)
{
    vaild = level != 0;
    if (vaild) std::fprintf(stderr, "[sdk %s %s:%d] ", prefix, func, line);
    return *this;
}
Log &Log::print() { return *this; }
Log &Log::print(const char *fmt, ...)
{
    if (vaild) {
        va_list args;
        va_start(args, fmt);
        std::vfprintf(stderr, fmt, args);
        va_end(args);
        std::fputc('\n', stderr);
    }
    return *this;
}

// ---- Vehicle: only what selects the broadcast unpacker -------------------------------------
// As in 3.4 to 3.9 (stubs.cpp): DataBroadcast::unpackCallback picks the
// legacy M600 unpacker for FW 3.2.15.62, the M100 one for FW 3.1.10.0, else
// the wider layout; okit_sdk::g_vehicle says which aircraft the adapter plays.
bool Vehicle::isM100() { return okit_sdk::g_vehicle == okit_sdk::VEHICLE_M100_FW31; }
bool Vehicle::isLegacyM600() { return okit_sdk::g_vehicle == okit_sdk::VEHICLE_M600_LEGACY; }
Version::FirmWare Vehicle::getFwVersion() const
{
    return okit_sdk::g_vehicle == okit_sdk::VEHICLE_M100_FW31 ? Version::M100_31 : Version::FW(3, 2, 15, 62);
}
int Vehicle::callbackIdIndex() { okit_sdk::not_reached("Vehicle::callbackIdIndex"); }
void *Vehicle::waitForACK(const uint8_t (&)[OpenProtocol::MAX_CMD_ARRAY_SIZE], int)
{
    okit_sdk::not_reached("Vehicle::waitForACK");
}

} // namespace OSDK
} // namespace DJI
