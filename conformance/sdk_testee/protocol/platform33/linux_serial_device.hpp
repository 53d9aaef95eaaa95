// Stand-in for the Linux platform layer of Onboard-SDK 3.3.x, found before
// the SDK's own platform headers (the Recipe leaves osdk-core/platform/linux
// off the include path). Ours, for three reasons:
//  - 3.3's single-class Protocol constructs its serial device and thread
//    handle itself, by these class names, so the stub serial device has to
//    be this class;
//  - the SDK's own header of it does not compile against current glibc
//    (it names fd_set without including <sys/select.h>);
//  - 3.3's receive pipeline has one observation point, its frame trace
//    (printFrame under API_TRACE_DATA, at the entry of the application
//    layer). 3.1 and 3.2 declared printFrame in their logging header; 3.3
//    still calls it but declares it nowhere, so the first platform header
//    its protocol file includes is where this build declares it. The
//    definition is a log stub (stubs33.cpp).
#ifndef OKIT_SDK_PLATFORM33_SERIAL_H
#define OKIT_SDK_PLATFORM33_SERIAL_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dji_hard_driver.hpp"
#include "dji_type.hpp"

namespace DJI
{
namespace OSDK
{

// The serial device: reads hand out the request's bytes in its chunks.
class LinuxSerialDevice : public HardDriver
{
  public:
    LinuxSerialDevice(const char *device, uint32_t baudrate);
    ~LinuxSerialDevice();
    void init();
    time_ms getTimeStamp();
    size_t send(const uint8_t *buf, size_t len);
    // Throws okit_sdk::Drained once the input is used up: Protocol::receive()
    // polls until it has a frame, and this is its only way back to the adapter.
    size_t readall(uint8_t *buf, size_t maxlen);
    bool drained() const;

    std::vector<uint8_t> input;
    std::vector<uint64_t> chunks;   // read sizes; the rest of the input is one last read
    size_t next_chunk;
    size_t taken_of_chunk;
    size_t pos;                      // bytes handed out so far
    size_t last_base;                // stream offset of the last read's first byte
    std::vector<uint8_t> sent;       // what the SDK wrote to the port
};

void printFrame(HardDriver *driver, Header *header, bool toAircraft);

} // namespace OSDK
} // namespace DJI

#endif
