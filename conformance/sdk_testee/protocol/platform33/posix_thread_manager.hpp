// Stand-in for 3.3's POSIX thread handle (see linux_serial_device.hpp here):
// the testee runs one thread, so the locks the protocol takes do nothing.
#ifndef OKIT_SDK_PLATFORM33_THREAD_MANAGER_H
#define OKIT_SDK_PLATFORM33_THREAD_MANAGER_H

#include "dji_thread_manager.hpp"

namespace DJI
{
namespace OSDK
{

class PosixThreadManager : public ThreadAbstract
{
  public:
    void init();
    void lockMemory();
    void freeMemory();
    void lockMSG();
    void freeMSG();
    void lockACK();
    void freeACK();
    void notify();
    void wait(int timeout);
};

} // namespace OSDK
} // namespace DJI

#endif
