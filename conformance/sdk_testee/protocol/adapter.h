// The "protocol"-family adapter (Onboard-SDK 3.3 to 3.9): shared declarations
// of adapter.cpp and the stubs (stubs.cpp for 3.4 to 3.9, stubs33.cpp and
// platform33/ for 3.3.x, whose Recipe defines OKIT_SDK_PROTOCOL_33).
//
// The SDK keeps its receive pipeline (checkStream, verifyHead, verifyData,
// callApp, the CRC functions, encrypt) private. Our code only calls and
// observes those members, so the access specifiers are lifted for this
// testee's own translation units; the standard headers come first so that
// only the SDK's classes are affected. The SDK's files are compiled as they
// are, and access does not change a class's layout.
#ifndef OKIT_SDK_PROTOCOL_ADAPTER_H
#define OKIT_SDK_PROTOCOL_ADAPTER_H

#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>
#include <map>
#include <list>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <atomic>
#include <condition_variable>
#include <pthread.h>

#define private public
#define protected public
#include "dji_open_protocol.hpp"
#ifndef OKIT_SDK_PROTOCOL_33
#include "dji_platform_manager.hpp"
#endif
#include "dji_broadcast.hpp"
#include "dji_vehicle.hpp"
#undef private
#undef protected

namespace okit_sdk {

#ifdef OKIT_SDK_PROTOCOL_33
// 3.3.x: one Protocol class with no virtual pipeline steps. Its serial
// device is the platform class it constructs itself (platform33/).
typedef DJI::OSDK::Protocol Link;
typedef DJI::OSDK::Header FrameHead;
typedef DJI::OSDK::LinuxSerialDevice StubDriver;

// Thrown by the serial stub when the request's bytes are used up.
struct Drained {};

// From the stubs to the adapter: the SDK's frame trace (printFrame on the
// receive side), and a serial read about to hand out the next bytes.
void trace_frame(const DJI::OSDK::Header *head);
void before_read(const StubDriver *driver);
#else
typedef DJI::OSDK::OpenProtocol Link;
typedef DJI::OSDK::OpenHeader FrameHead;

// The serial device: reads hand out the request's bytes in its chunks.
class StubDriver : public DJI::OSDK::HardDriver
{
  public:
    StubDriver();
    void init();
    DJI::OSDK::time_ms getTimeStamp();
    size_t send(const uint8_t *buf, size_t len);
    size_t readall(uint8_t *buf, size_t maxlen);
    bool drained() const;

    std::vector<uint8_t> input;
    std::vector<uint64_t> chunks;   // read sizes; the rest of the input is one last read
    size_t next_chunk = 0;
    size_t taken_of_chunk = 0;
    size_t pos;                      // bytes handed out so far
    size_t base;
    size_t last_base;                // stream offset of the last read's first byte
    std::vector<uint8_t> sent;       // what the SDK wrote to the port
};

class StubThread : public DJI::OSDK::ThreadAbstract
{
  public:
    void lockRecvContainer();
    void freeRecvContainer();
    void lockMSG();
    void freeMSG();
    void lockACK();
    void freeACK();
    void notify();
    void wait(int timeout);
    void init();
};
#endif

enum VehicleKind { VEHICLE_M100_FW31, VEHICLE_M600_LEGACY };
extern VehicleKind g_vehicle;

[[noreturn]] void not_reached(const char *what);

} // namespace okit_sdk

#endif
