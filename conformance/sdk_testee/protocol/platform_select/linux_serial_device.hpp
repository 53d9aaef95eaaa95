// Onboard-SDK 3.4 to 3.6 declare their Linux serial device with an fd_set
// member without including <sys/select.h> (3.7 added it), and current glibc
// no longer brings it in through the headers they do include. The testee
// never constructs that device (stubs.cpp's PlatformManager hands out the
// stub), but dji_platform_manager.hpp includes its header, so the Recipe puts
// this directory first for those trees: the system header, then the SDK's
// own header, unchanged.
#include <sys/select.h>
#include_next "linux_serial_device.hpp"
