// Stand-in for 3.3's POSIX reader/callback threads (see
// linux_serial_device.hpp here). dji_vehicle.hpp includes it only for the
// platform's Thread subclass, which the testee never starts: the adapter
// calls Protocol::receive() itself, as that thread would.
#ifndef OKIT_SDK_PLATFORM33_THREAD_H
#define OKIT_SDK_PLATFORM33_THREAD_H

#include "dji_thread_manager.hpp"

#endif
