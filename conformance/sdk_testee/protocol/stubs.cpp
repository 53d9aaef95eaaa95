// Stubs for the parts of a "protocol"-family Onboard-SDK (3.4 to 3.9) that
// the OPEN protocol does not need: the serial port, the threads and
// mutexes, the log, the clock, and the few Vehicle members the broadcast
// unpacker asks. Everything here is ours; the SDK's own files are compiled
// unchanged beside it (osdk_conformance/sdk/families/protocol.py lists them).
//
// What a stub does, and why:
//  - the serial device reads the bytes the adapter queued (one read per
//    chunk, as a UART driver returns them), sends into a capture buffer, and
//    its clock stands still: session timeouts are never reached in one request;
//  - locks do nothing: the testee runs one thread;
//  - the log writes to stderr, never stdout (stdout carries the JSON answers);
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

StubDriver::StubDriver() : pos(0), base(0), last_base(0) {}
void StubDriver::init() {}
time_ms StubDriver::getTimeStamp() { return 0; }
size_t StubDriver::send(const uint8_t *data, size_t len)
{
    sent.insert(sent.end(), data, data + len);
    return len;
}
size_t StubDriver::readall(uint8_t *out, size_t maxlen)
{
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
    return 0;
}
bool StubDriver::drained() const { return next_chunk >= chunks.size(); }

void StubThread::lockRecvContainer() {}
void StubThread::freeRecvContainer() {}
void StubThread::lockMSG() {}
void StubThread::freeMSG() {}
void StubThread::lockACK() {}
void StubThread::freeACK() {}
void StubThread::notify() {}
void StubThread::wait(int) {}
void StubThread::init() {}

VehicleKind g_vehicle = VEHICLE_M100_FW31;

[[noreturn]] void not_reached(const char *what)
{
    std::fprintf(stderr, "sdk testee: stub %s reached; the claimed operations never call it\n", what);
    std::abort();
}

} // namespace okit_sdk

// ---- platform manager: hands the SDK our serial device and thread handle --------------------
namespace DJI {
namespace OSDK {

PlatformManager::PlatformManager() {}
PlatformManager::~PlatformManager() {}
HardDriver *PlatformManager::addHardDriver(uint8_t, const char *, uint32_t) { return new okit_sdk::StubDriver(); }
ThreadAbstract *PlatformManager::addThreadHandle() { return new okit_sdk::StubThread(); }

// ---- log: to stderr ----------------------------------------------------------------------
Log::Log(Mutex *m) : mutex(m), vaild(true), enable_status(true), enable_debug(false), enable_error(true) {}
Log::~Log() {}
Log &Log::title(int level, const char *prefix, const char *func, int line)
{
    vaild = level != 0;
    if (vaild) std::fprintf(stderr, "[sdk %s %s:%d] ", prefix, func, line);
    return *this;
}
#ifndef OKIT_SDK_LOG_NO_SHORT_TITLE   // 3.4.x has only the four-argument title
Log &Log::title(int level, const char *prefix)
{
    vaild = level != 0;
    if (vaild) std::fprintf(stderr, "[sdk %s] ", prefix);
    return *this;
}
#endif
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
bool Log::getStatusLogState() { return enable_status; }
bool Log::getDebugLogState() { return enable_debug; }
bool Log::getErrorLogState() { return enable_error; }

// ---- Vehicle: only what selects the broadcast unpacker -------------------------------------
// The SDK picks its unpacker from the aircraft's firmware and hardware
// version (DataBroadcast::unpackCallback): the M100 on FW 3.1.10.0, the
// legacy M600 on FW 3.2.15.62, else the wider 3.2+ layout. The adapter says
// which aircraft it plays through okit_sdk::g_vehicle.
bool Vehicle::isM100() { return okit_sdk::g_vehicle == okit_sdk::VEHICLE_M100_FW31; }
bool Vehicle::isLegacyM600() { return okit_sdk::g_vehicle == okit_sdk::VEHICLE_M600_LEGACY; }
Version::FirmWare Vehicle::getFwVersion() const
{
    return okit_sdk::g_vehicle == okit_sdk::VEHICLE_M100_FW31 ? Version::M100_31 : Version::FW(3, 2, 15, 62);
}
int Vehicle::callbackIdIndex() { okit_sdk::not_reached("Vehicle::callbackIdIndex"); }
bool Vehicle::getEncryption() { okit_sdk::not_reached("Vehicle::getEncryption"); }
void *Vehicle::waitForACK(const uint8_t (&)[OpenProtocolCMD::MAX_CMD_ARRAY_SIZE], int)
{
    okit_sdk::not_reached("Vehicle::waitForACK");
}

} // namespace OSDK
} // namespace DJI
