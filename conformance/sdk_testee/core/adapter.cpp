// The testee for DJI Onboard-SDK releases of the "core" family (2.3, 3.1.x,
// 3.2.x: CoreAPI, DJI_Link, DJI_Codec), on the testee kit (okit.h).
//
// The SDK's receive path runs as shipped: bytes go one at a time into
// CoreAPI::byteHandler (what readPoll does with each read), which assembles
// the frame, checks the header, the CRC-32, decrypts and hands the frame to
// CoreAPI::appHandler. DJI_Codec.cpp is compiled inside this file (below)
// with one preprocessor change: its single call of appHandler goes through
// tap(), which records the frame the frame layer delivers and then calls the
// SDK's own appHandler, so the SDK's dispatch (session tables, recvReqData,
// the broadcast unpacker) still runs on every delivered frame. Nothing else
// of the SDK is changed; DJI code is never copied here.
//
// Build-time knowledge of the release comes from osdk_conformance/sdk/families/core.py:
//   OSDKC_CORE_VERSION   230, 317, 318, 319, 320, 322
//   OSDKC_CORE_PROFILES  the wire profiles its broadcast unpacker speaks (see core.py)
// See conformance/sdk_testee/core/README.md for how each answer is derived.

#include <DJI_API.h>
#include <DJI_Codec.h>
#include <DJI_HardDriver.h>
#include <DJI_Link.h>

#include <new>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <string>
#include <vector>

// DJI_App.cpp's readers of cmd set and id (defined there, declared in no header)
unsigned char getCmdSet(DJI::onboardSDK::Header *protocolHeader);
unsigned char getCmdCode(DJI::onboardSDK::Header *protocolHeader);

namespace osdkc {
void tap(DJI::onboardSDK::CoreAPI *api, DJI::onboardSDK::Header *header);
}

// The frame layer, compiled unchanged except for the hand-over to appHandler.
#define appHandler(h) ::osdkc::tap(this, h)
#include "DJI_Codec.cpp"
#undef appHandler

#include "okit.h"

using namespace DJI::onboardSDK;

#ifndef OSDKC_CORE_VERSION
#error "OSDKC_CORE_VERSION must be defined (osdk_conformance/sdk/families/core.py)"
#endif

// ---- access to the SDK's private members, without changing its headers --------------------------
// (an explicit instantiation may name private members: the standard's own exception)

namespace {
template <class Tag, typename Tag::type M>
struct Rob {
  friend typename Tag::type get(Tag) { return M; }
};
struct FilterM { typedef SDKFilter CoreAPI::*type; friend type get(FilterM); };
struct BroadcastDataM { typedef BroadcastData CoreAPI::*type; friend type get(BroadcastDataM); };
struct VersionDataM { typedef VersionData CoreAPI::*type; friend type get(VersionDataM); };
struct AppHandlerM { typedef void (CoreAPI::*type)(Header *); friend type get(AppHandlerM); };
struct BroadcastM { typedef void (CoreAPI::*type)(Header *); friend type get(BroadcastM); };
struct AckInterfaceM { typedef int (CoreAPI::*type)(Ack *); friend type get(AckInterfaceM); };
struct EncryptM {
  typedef unsigned short (CoreAPI::*type)(unsigned char *, const unsigned char *, unsigned short,
                                          unsigned char, unsigned char, unsigned char, unsigned short);
  friend type get(EncryptM);
};
}  // namespace
template struct Rob<FilterM, &CoreAPI::filter>;
template struct Rob<BroadcastDataM, &CoreAPI::broadcastData>;
template struct Rob<VersionDataM, &CoreAPI::versionData>;
template struct Rob<AppHandlerM, &CoreAPI::appHandler>;
template struct Rob<BroadcastM, &CoreAPI::broadcast>;
template struct Rob<AckInterfaceM, &CoreAPI::ackInterface>;
template struct Rob<EncryptM, &CoreAPI::encrypt>;

// ---- the platform stub: no port, no threads; logs to stderr ---------------------------------------

namespace {
std::vector<uint8_t> g_sent;   // what the SDK wrote to its serial device

class StubDriver : public HardDriver {
 public:
  void init() {}
  DJI::time_ms getTimeStamp() { return 0; }
  size_t send(const uint8_t *buf, size_t len) {
    g_sent.assign(buf, buf + len);
    return len;
  }
  size_t readall(uint8_t *, size_t) { return 0; }
  void lockMemory() {}
  void freeMemory() {}
  void lockMSG() {}
  void freeMSG() {}
  void lockACK() {}
  void freeACK() {}
  void notify() {}
  void wait(int) {}
#if OSDKC_CORE_VERSION == 230
  void displayLog(char *buf = 0) { log(buf); }
#else
  void displayLog(const char *buf = 0) { log(buf); }
#endif
 private:
  static void log(const char *buf) {
    // the SDK's messages go to stderr: stdout carries the testee protocol
    fprintf(stderr, "sdk: %s", buf ? buf : DJI::onboardSDK::buffer);
  }
};

StubDriver g_driver;

// ---- profiles ---------------------------------------------------------------------------------

enum Profile { M100_23, M100_31, A3_31 };
struct ProfileInfo {
  const char *id;
  Profile p;
};
const ProfileInfo ALL_PROFILES[] = {{"m100-fw2.3", M100_23}, {"m100-fw3.1", M100_31}, {"a3-fw3.1", A3_31}};

#ifndef OSDKC_CORE_PROFILES
#define OSDKC_CORE_PROFILES 7   // bit i: ALL_PROFILES[i]
#endif
const char *g_profile_ids[4];
Profile g_profile_of[4];

// A fresh CoreAPI per request (no state carried from one case to the next), in
// zeroed memory so that what the SDK never initialises (its AES key) is the same every run.
struct Api {
  CoreAPI *api;
  void *mem;
  explicit Api(Profile p) {
    mem = calloc(1, sizeof(CoreAPI));
#if OSDKC_CORE_VERSION == 230 || OSDKC_CORE_VERSION == 322
    api = new (mem) CoreAPI(&g_driver);
#else
    api = new (mem) CoreAPI(&g_driver, version_of(p));
#endif
#if OSDKC_CORE_VERSION == 322
    // 3.2.2 takes the layout from what the version ACK told it (hardware name, firmware
    // version); these are the values an M100 on 3.1 / 2.3 and an A3 on 3.1 report.
    VersionData &v = api->*get(VersionDataM());
    strcpy(v.hwVersion, p == A3_31 ? "A3" : "M100");
    v.fwVersion = p == M100_23 ? MAKE_VERSION(2, 3, 10, 0) : p == M100_31 ? MAKE_VERSION(3, 1, 10, 0)
                                                                            : MAKE_VERSION(3, 1, 100, 0);
#endif
  }
  ~Api() { free(mem); }   // the SDK's objects hold no heap memory of their own worth a destructor here
#if OSDKC_CORE_VERSION != 230 && OSDKC_CORE_VERSION != 322
  static Version version_of(Profile p) {
    return p == M100_23 ? versionM100_23 : p == M100_31 ? versionM100_31 : versionA3_31;
  }
#endif
};

// ---- what the frame layer delivered ------------------------------------------------------------

struct Delivered {
  size_t offset;             // of the frame's first byte in the input
  size_t len;                // the SDK's receive index at delivery: the wire LEN
  std::vector<uint8_t> sdk;  // the frame as the SDK handed it over (DATA decrypted when ENC != 0)
  bool consistent;           // the input at `offset` is the frame the SDK checked
  bool broadcast;            // a plain command 0x02/0x00: the SDK's unpacker ran on it
  BroadcastData bc;
};

const uint8_t *g_in;
size_t g_in_len;
size_t g_fed;   // bytes given to byteHandler so far, the current one included
std::vector<Delivered> g_out;
}  // namespace

void osdkc::tap(CoreAPI *api, Header *header) {
  SDKFilter &f = api->*get(FilterM());
  Delivered d;
  // The SDK's bytes still to be looked at are recvBuf[0, recvIndex) then the replay area
  // recvBuf[reuseIndex, end): together always the input's bytes just before the next one to feed.
  size_t pending = (size_t)_SDK_MAX_RECV_SIZE - f.reuseIndex;
  d.len = f.recvIndex;
  d.offset = g_fed - pending - d.len;
  const uint8_t *frame = (const uint8_t *)header;
  size_t keep = d.len < 1024 ? d.len : 1024;
  d.sdk.assign(frame, frame + keep);
  d.consistent = d.offset + d.len <= g_in_len && memcmp(g_in + d.offset, frame, 12 < d.len ? 12 : d.len) == 0;
  if (header->enc == 0)
    d.consistent = d.consistent && memcmp(g_in + d.offset, frame, d.len) == 0;
  else   // decrypting shortens the SDK's length field by PADDING; the rest of the header is as received
    d.consistent = d.offset + d.len <= g_in_len;
  d.broadcast = false;
  memset(&d.bc, 0, sizeof d.bc);
  if (!header->isAck && header->enc == 0 && d.len > 12 && getCmdSet(header) == 0x02 && getCmdCode(header) == 0x00) {
    // the SDK's broadcast unpacker, on the frame as recvReqData passes it
    (api->*get(BroadcastM()))(header);
    d.broadcast = true;
    d.bc = api->*get(BroadcastDataM());
  }
  g_out.push_back(d);
  (api->*get(AppHandlerM()))(header);   // the SDK's own dispatch of the frame
}

// ---- writing the value model ---------------------------------------------------------------------

namespace {

uint32_t bits32(const void *p) {
  uint32_t u;
  memcpy(&u, p, 4);
  return u;
}
uint64_t bits64(const void *p) {
  uint64_t u;
  memcpy(&u, p, 8);
  return u;
}

const char *control_device_name(unsigned v) {
  static const char *n[] = {"rc", "mobile_device", "onboard_device"};
  return v < 3 ? n[v] : 0;
}

const char *mov_mode_name(unsigned v) {
  static const char *n[] = {"atti_stop",
                            "horiz_ang_vert_vel_yaw_ang", "horiz_ang_vert_vel_yaw_rate",
                            "horiz_vel_vert_vel_yaw_ang", "horiz_vel_vert_vel_yaw_rate",
                            "horiz_pos_vert_vel_yaw_ang", "horiz_pos_vert_vel_yaw_rate",
                            "horiz_ang_vert_pos_yaw_ang", "horiz_ang_vert_pos_yaw_rate",
                            "horiz_vel_vert_pos_yaw_ang", "horiz_vel_vert_pos_yaw_rate",
                            "horiz_pos_vert_pos_yaw_ang", "horiz_pos_vert_pos_yaw_rate",
                            "horiz_ang_vert_thr_yaw_ang", "horiz_ang_vert_thr_yaw_rate",
                            "horiz_vel_vert_thr_yaw_ang", "horiz_vel_vert_thr_yaw_rate",
                            "horiz_pos_vert_thr_yaw_ang", "horiz_pos_vert_thr_yaw_rate"};
  static const char *m[] = {"gps_atti_ctrl_cl_yaw_rate", "gps_atti_ctrl_yaw_rate", "atti_ctrl_yaw_rate",
                            "atti_ctrl_stop"};
  if (v <= 18) return n[v];
  if (v >= 97 && v <= 100) return m[v - 97];
  return 0;
}

void key_f32(osdk_json_t *w, const char *k, const void *p) {
  osdk_json_key(w, k);
  osdk_json_f32(w, bits32(p));
}
void key_f64(osdk_json_t *w, const char *k, const void *p) {
  osdk_json_key(w, k);
  osdk_json_f64(w, bits64(p));
}
void key_int(osdk_json_t *w, const char *k, int64_t v) {
  osdk_json_key(w, k);
  osdk_json_int(w, v);
}
void key_bool(osdk_json_t *w, const char *k, bool v) {
  osdk_json_key(w, k);
  osdk_json_bool(w, v);
}
void vec3(osdk_json_t *w, const char *k, const CommonData &c) {
  osdk_json_key(w, k);
  osdk_json_begin_object(w);
  key_f32(w, "x", &c.x);
  key_f32(w, "y", &c.y);
  key_f32(w, "z", &c.z);
  osdk_json_end_object(w);
}

// The broadcast as the SDK unpacked it into its BroadcastData: each item whose flag bit is
// set, read from the SDK's structure (floats as their bits; a byte of bit fields from the
// byte the SDK stored, whatever names its own bit fields give to it).
void write_broadcast(osdk_json_t *w, const BroadcastData &b, Profile p) {
  static const char *m100_items[] = {"time_stamp", "quaternion", "acceleration", "velocity", "angular_rate",
                                     "position", "magnetometer", "rc", "gimbal", "flight_status", "battery",
                                     "control_info"};
  static const char *a3_items[] = {"time_stamp", "quaternion", "acceleration", "velocity", "angular_rate",
                                   "position", "gps_detail", "rtk_detail", "magnetometer", "rc", "gimbal",
                                   "flight_status", "battery", "control_info"};
  const char **items = p == A3_31 ? a3_items : m100_items;
  unsigned n = p == A3_31 ? 14 : 12;
  unsigned flags = b.dataFlag;
  osdk_json_begin_object(w);
  osdk_json_key(w, "data");
  osdk_json_begin_object(w);
  for (unsigned i = 0; i < n; i++) {
    std::string k = std::string("has_") + items[i];
    key_bool(w, k.c_str(), (flags >> i) & 1);
  }
  key_int(w, "reserved_flags", flags >> n);
  for (unsigned i = 0; i < n; i++) {
    if (!((flags >> i) & 1)) continue;
    std::string it = items[i];
    if (it == "time_stamp") {
      osdk_json_key(w, "time_stamp");
      osdk_json_begin_object(w);
#if OSDKC_CORE_VERSION == 230
      key_int(w, "time", b.timeStamp);   // 2.3 built for firmware 2.3: the time stamp is the u32 alone
#else
      key_int(w, "time", b.timeStamp.time);
      if (p != M100_23) {
        key_int(w, "nano_time", b.timeStamp.nanoTime);
        key_int(w, "sync_flag", b.timeStamp.syncFlag);
      }
#endif
      osdk_json_end_object(w);
    } else if (it == "quaternion") {
      osdk_json_key(w, "quaternion");
      osdk_json_begin_object(w);
      key_f32(w, "q0", &b.q.q0);
      key_f32(w, "q1", &b.q.q1);
      key_f32(w, "q2", &b.q.q2);
      key_f32(w, "q3", &b.q.q3);
      osdk_json_end_object(w);
    } else if (it == "acceleration") {
      vec3(w, "acceleration", b.a);
    } else if (it == "angular_rate") {
      vec3(w, "angular_rate", b.w);
    } else if (it == "velocity") {
      const uint8_t *raw = (const uint8_t *)&b.v;
      uint8_t fl = raw[12];   // the byte after the three floats, as the SDK stored it
      osdk_json_key(w, "velocity");
      osdk_json_begin_object(w);
      key_f32(w, "x", &b.v.x);
      key_f32(w, "y", &b.v.y);
      key_f32(w, "z", &b.v.z);
      key_bool(w, "data_valid", fl & 1);
      key_int(w, "sensor_id", (fl >> 1) & 0xF);
      key_int(w, "reserved", fl >> 5);
      osdk_json_end_object(w);
    } else if (it == "position") {
      osdk_json_key(w, "position");
      osdk_json_begin_object(w);
      key_f64(w, "latitude", &b.pos.latitude);
      key_f64(w, "longitude", &b.pos.longitude);
      key_f32(w, "altitude", &b.pos.altitude);
      key_f32(w, "height", &b.pos.height);
      key_int(w, "gps_health", b.pos.health);
      osdk_json_end_object(w);
#if OSDKC_CORE_VERSION != 230
    } else if (it == "gps_detail") {
      osdk_json_key(w, "gps_detail");
      osdk_json_begin_object(w);
      key_int(w, "date", b.gps.date);
      key_int(w, "time", b.gps.time);
      key_int(w, "longitude", b.gps.longitude);
      key_int(w, "latitude", b.gps.latitude);
      key_int(w, "height_msl", b.gps.Hmsl);
      key_f32(w, "vel_n", &b.gps.velocityNorth);
      key_f32(w, "vel_e", &b.gps.velocityEast);
      key_f32(w, "vel_d", &b.gps.velocityGround);
      osdk_json_end_object(w);
    } else if (it == "rtk_detail") {
      osdk_json_key(w, "rtk_detail");
      osdk_json_begin_object(w);
      key_int(w, "date", b.rtk.date);
      key_int(w, "time", b.rtk.time);
      key_f64(w, "longitude", &b.rtk.longitude);
      key_f64(w, "latitude", &b.rtk.latitude);
      key_f32(w, "height_msl", &b.rtk.Hmsl);
      key_f32(w, "vel_n", &b.rtk.velocityNorth);
      key_f32(w, "vel_e", &b.rtk.velocityEast);
      key_f32(w, "vel_d", &b.rtk.velocityGround);
      key_int(w, "yaw", b.rtk.yaw);
      key_int(w, "position_flag", b.rtk.posFlag);
      key_int(w, "yaw_flag", b.rtk.yawFlag);
      osdk_json_end_object(w);
#endif
    } else if (it == "magnetometer") {
      osdk_json_key(w, "magnetometer");
      osdk_json_begin_object(w);
      key_int(w, "x", b.mag.x);
      key_int(w, "y", b.mag.y);
      key_int(w, "z", b.mag.z);
      osdk_json_end_object(w);
    } else if (it == "rc") {
      osdk_json_key(w, "rc");
      osdk_json_begin_object(w);
      key_int(w, "roll", b.rc.roll);
      key_int(w, "pitch", b.rc.pitch);
      key_int(w, "yaw", b.rc.yaw);
      key_int(w, "throttle", b.rc.throttle);
      key_int(w, "mode", b.rc.mode);
      key_int(w, "gear", b.rc.gear);
      osdk_json_end_object(w);
    } else if (it == "gimbal") {
      osdk_json_key(w, "gimbal");
      osdk_json_begin_object(w);
      key_f32(w, "roll", &b.gimbal.roll);
      key_f32(w, "pitch", &b.gimbal.pitch);
      key_f32(w, "yaw", &b.gimbal.yaw);
      if (p != M100_23) {
        const uint8_t *raw = (const uint8_t *)&b.gimbal;
        uint8_t fl = sizeof(b.gimbal) > 12 ? raw[12] : 0;
        osdk_json_key(w, "limit");
        osdk_json_begin_object(w);
        key_bool(w, "pitch_limit", fl & 1);
        key_bool(w, "roll_limit", (fl >> 1) & 1);
        key_bool(w, "yaw_limit", (fl >> 2) & 1);
        key_int(w, "reserved", fl >> 3);
        osdk_json_end_object(w);
      }
      osdk_json_end_object(w);
    } else if (it == "flight_status") {
      key_int(w, "flight_status", (uint8_t)b.status);
    } else if (it == "battery") {
      key_int(w, "battery", (uint8_t)b.battery);
    } else if (it == "control_info") {
      const uint8_t *raw = (const uint8_t *)&b.ctrlInfo;
      // 2.3's CtrlInfoData is the flag byte alone; later ones put the mode byte first
      uint8_t fl = sizeof(b.ctrlInfo) >= 2 ? raw[1] : raw[0];
      osdk_json_key(w, "control_info");
      osdk_json_begin_object(w);
      if (p != M100_23) {
        osdk_json_key(w, "cur_mov_control_mode");
        osdk_json_enum(w, raw[0], mov_mode_name(raw[0]));
      }
      osdk_json_key(w, "control_device");
      osdk_json_enum(w, fl & 7, control_device_name(fl & 7));
      key_bool(w, "onboard_requested", (fl >> 3) & 1);
      key_bool(w, "virtual_rc", (fl >> 4) & 1);
      key_int(w, "reserved", fl >> 5);
      osdk_json_end_object(w);
    }
  }
  osdk_json_end_object(w);
  osdk_json_end_object(w);
}

// The spec's typed command values other than the broadcast: the SDK only ever sends these,
// it has no decoder for them, so a frame carrying one is not answered (unsupported).
bool sdk_cannot_decode(unsigned set, unsigned id) {
  unsigned key = set << 8 | id;
  return key == 0x0000 || key == 0x0001 || key == 0x0010 || key == 0x0100 || key == 0x0103 || key == 0x0201;
}

// Header fields as the SDK's own Header structure reads the bytes it checked.
Header header_of(const uint8_t *p) {
  Header h;
  memcpy(&h, p, sizeof h);
  return h;
}

// Whether a delivered frame can be written: false when its value needs a decoder the SDK lacks.
bool writable(const Delivered &d) {
  Header h = header_of(g_in + d.offset);
  if (h.isAck || h.enc != 0 || d.len < 16) return true;
  if (d.len < 18) return true;   // cmd set/id are read from the bytes the SDK reads them from
  return d.broadcast || !sdk_cannot_decode(d.sdk[12], d.sdk[13]);
}

void write_frame(osdk_json_t *w, const Delivered &d, Profile p) {
  const uint8_t *in = g_in + d.offset;
  Header h = header_of(in);
  osdk_json_begin_object(w);
  osdk_json_key(w, "sof");
  osdk_json_hex(w, in, 1);
  key_int(w, "len", d.len);   // the wire LEN: the SDK shortens its copy by PADDING when it decrypts
  key_int(w, "ver", h.version);
  key_int(w, "session", h.sessionID);
  key_bool(w, "is_ack", h.isAck);
  key_int(w, "res0", h.reversed0);
  key_int(w, "padding", h.padding);
  osdk_json_key(w, "enc");
  osdk_json_enum(w, h.enc, h.enc == 0 ? "plain" : h.enc == 1 ? "aes256" : 0);
  key_int(w, "res1", h.reversed1);
  key_int(w, "seq", h.sequenceNumber);
  key_int(w, "crc16", h.crc);
  if (d.len > 12) {
    size_t data_len = d.len >= 16 ? d.len - 16 : 0;
    osdk_json_key(w, "data");
    if (h.enc != 0) {
      osdk_json_hex(w, in + 12, data_len);   // the DATA as received (the spec keeps ciphertext)
    } else if (h.isAck) {
      osdk_json_begin_object(w);
      osdk_json_key(w, "ack_value");
      osdk_json_hex(w, in + 12, data_len);
      osdk_json_end_object(w);
    } else {
      // cmd set and id as the SDK's recvReqData reads them (getCmdSet/getCmdCode), even
      // where DATA is shorter than two bytes and they come from the CRC-32
      Header *sh = (Header *)&d.sdk[0];
      osdk_json_begin_object(w);
      unsigned set = d.sdk.size() > 12 ? getCmdSet(sh) : 0, id = d.sdk.size() > 13 ? getCmdCode(sh) : 0;
      static const char *sets[] = {"activation", "control", "push"};
      osdk_json_key(w, "cmd_set");
      osdk_json_enum(w, set, set < 3 ? sets[set] : 0);
      key_int(w, "cmd_id", id);
      osdk_json_key(w, "value");
      if (d.broadcast) {
        osdk_json_begin_object(w);
        osdk_json_key(w, "body");
        write_broadcast(w, d.bc, p);
        osdk_json_end_object(w);
      } else {
        osdk_json_begin_object(w);
        osdk_json_key(w, "body");
        osdk_json_begin_object(w);
        osdk_json_key(w, "raw");
        osdk_json_hex(w, in + 14, data_len >= 2 ? data_len - 2 : 0);
        osdk_json_end_object(w);
        osdk_json_end_object(w);
      }
      osdk_json_end_object(w);
    }
    key_int(w, "crc32", bits32(in + d.len - 4) );
  }
  osdk_json_end_object(w);
}

Profile profile_of(okit_request *req) { return g_profile_of[okit_profile(req)]; }

// Feed `n` bytes through the SDK's receive path, one byteHandler call per byte.
void feed(CoreAPI *api, const uint8_t *p, size_t n) {
  g_in = p;
  g_in_len = n;
  g_out.clear();
  for (g_fed = 0; g_fed < n;) {
    uint8_t b = p[g_fed];
    g_fed++;
    api->byteHandler(b);
  }
}

bool all_consistent(okit_request *req) {
  for (size_t i = 0; i < g_out.size(); i++)
    if (!g_out[i].consistent) {
      okit_error(req, "internal_error", "adapter: the frame the SDK delivered is not the input at the derived offset");
      return false;
    }
  return true;
}

// ---- decode_stream ------------------------------------------------------------------------------

void decode_stream(okit_request *req) {
  uint8_t *in;
  size_t n;
  uint64_t *chunks;
  size_t nc;
  if (!okit_hex(req, "hex", &in, &n)) return;
  if (!okit_sizes(req, "chunks", &chunks, &nc)) {
    free(in);
    return;
  }
  free(chunks);   // one byte at a time, as readPoll hands every read to byteHandler: reads do not matter
  Profile p = profile_of(req);
  {
    Api a(p);
    feed(a.api, in, n);
  }
  if (!all_consistent(req)) {
    free(in);
    return;
  }
  for (size_t i = 0; i < g_out.size(); i++)
    if (!writable(g_out[i])) {
      free(in);
      okit_unsupported(req);
      return;
    }
  osdk_json_t *w = okit_result(req, 4096 + g_out.size() * 8192);
  if (w) {
    osdk_json_begin_object(w);
    osdk_json_key(w, "events");
    osdk_json_begin_array(w);
    for (size_t i = 0; i < g_out.size(); i++) {
      osdk_json_begin_object(w);
      osdk_json_key(w, "kind");
      osdk_json_string(w, "frame");
      key_int(w, "offset", g_out[i].offset);
      osdk_json_key(w, "frame");
      write_frame(w, g_out[i], p);
      osdk_json_end_object(w);
    }
    osdk_json_end_array(w);
    osdk_json_end_object(w);
  }
  free(in);
}

// ---- decode_frame -------------------------------------------------------------------------------

// The class of a frame the SDK did not deliver, from the SDK's own checks on it (README.md).
const char *rejection(const uint8_t *in, size_t n, std::string &detail) {
  if (n < sizeof(Header)) {
    detail = "fewer than 12 bytes: checkStream waits for a whole header";
    return "truncated_frame";
  }
  Header h = header_of(in);
  bool sof = h.sof == _SDK_SOF, ver = h.version == 0, res0 = h.reversed0 == 0, res1 = h.reversed1 == 0;
#if OSDKC_CORE_VERSION == 230
  bool len = h.length <= _SDK_MAX_RECV_SIZE;
#else
  bool len = h.length < _SDK_MAX_RECV_SIZE;
#endif
  bool crc = _SDK_CALC_CRC_HEAD((void *)in, sizeof(Header)) == 0;
  if (!(sof && ver && len && res0 && res1 && crc)) {
    detail = "verifyHead rejects the header";
    if (!sof) return "bad_sof";
    if (!crc) return "bad_crc16";
    if (!ver) return "bad_version";
    if (!res0 || !res1) return "reserved_bits";
    return "impossible_length";
  }
  if (h.length < sizeof(Header)) {
    detail = "verifyHead accepts LEN < 12; checkStream then waits for LEN bytes, which never comes";
    return "truncated_frame";
  }
  if (n < h.length) {
    detail = "the input ends before LEN bytes: checkStream waits";
    return "truncated_frame";
  }
  if (h.length > sizeof(Header) && _SDK_CALC_CRC_TAIL((void *)in, h.length) != 0) {
    detail = "verifyData: CRC-32 over LEN bytes is not 0";
    return "bad_crc32";
  }
  return 0;
}

void decode_frame(okit_request *req) {
  uint8_t *in;
  size_t n;
  if (!okit_hex(req, "hex", &in, &n)) return;
  Profile p = profile_of(req);
  {
    Api a(p);
    feed(a.api, in, n);
  }
  const Delivered *d = 0;
  for (size_t i = 0; i < g_out.size(); i++)
    if (g_out[i].offset == 0) {
      d = &g_out[i];
      break;
    }
  if (!all_consistent(req)) {
  } else if (d) {
    if (!writable(*d)) {
      okit_unsupported(req);
    } else {
      osdk_json_t *w = okit_result(req, 16384);
      if (w) {
        osdk_json_begin_object(w);
        osdk_json_key(w, "frame");
        write_frame(w, *d, p);
        osdk_json_end_object(w);
      }
    }
  } else {
    std::string detail;
    const char *cls = rejection(in, n, detail);
    if (cls)
      okit_error(req, cls, ("not delivered by the SDK: " + detail).c_str());
    else
      okit_error(req, "internal_error", "adapter: the SDK's checks pass but it delivered no frame at offset 0");
  }
  free(in);
}

// ---- decode_payload (the broadcast only) ---------------------------------------------------------

void decode_payload(okit_request *req) {
  int64_t set, id;
  bool is_ack;
  uint8_t *in;
  size_t n;
  if (!okit_int(req, "cmd_set", 0, 255, &set) || !okit_int(req, "cmd_id", 0, 255, &id) ||
      !okit_bool(req, "is_ack", &is_ack))
    return;
  if (is_ack || set != 0x02 || id != 0x00) {
    okit_unsupported(req);   // the broadcast is the only value the SDK's receive path unpacks
    return;
  }
  if (!okit_hex(req, "hex", &in, &n)) return;
  if (n + 2 > PRO_PURE_DATA_MAX_SIZE) {
    free(in);
    okit_unsupported(req);
    return;
  }
  Profile p = profile_of(req);
  bool ok = false;
  BroadcastData bc;
  {
    // the value goes in a session-0 command frame built by the SDK's own encoder, and
    // through its receive path to the unpacker, where a broadcast really arrives
    Api a(p);
    std::vector<uint8_t> cmd(n + 2);
    cmd[0] = 0x02;
    cmd[1] = 0x00;
    if (n) memcpy(&cmd[2], in, n);
    std::vector<uint8_t> frame(n + 2 + 16);
    unsigned short len = (a.api->*get(EncryptM()))(&frame[0], &cmd[0], (unsigned short)(n + 2), 0, 0, 0, 0);
    if (len == frame.size()) {
      feed(a.api, &frame[0], len);
      if (g_out.size() == 1 && g_out[0].broadcast) {
        ok = true;
        bc = g_out[0].bc;
      }
    }
  }
  free(in);
  if (!ok) {
    okit_error(req, "internal_error", "adapter: the SDK did not deliver the broadcast frame its encoder built");
    return;
  }
  osdk_json_t *w = okit_result(req, 16384);
  if (!w) return;
  osdk_json_begin_object(w);
  osdk_json_key(w, "value");
  write_broadcast(w, bc, p);
  osdk_json_end_object(w);
}

// ---- encode_frame -----------------------------------------------------------------------------

void encode_frame(okit_request *req) {
  bool is_ack;
  int64_t session, seq, set = 0, id = 0;
  uint8_t *value;
  size_t n;
  if (!okit_bool(req, "is_ack", &is_ack) || !okit_int(req, "session", 0, 31, &session) ||
      !okit_int(req, "seq", 0, 65535, &seq))
    return;
  if (!is_ack && (!okit_int(req, "cmd_set", 0, 255, &set) || !okit_int(req, "cmd_id", 0, 255, &id))) return;
  if (!okit_hex(req, "value", &value, &n)) return;
  Api a(M100_31);
  g_sent.clear();
  if (is_ack) {
    // the SDK's ACK sender: its length check, then nothing at all for session 0
    Ack ack;
    memset(&ack, 0, sizeof ack);
    ack.sessionID = (uint16_t)session;
    ack.seqNum = (uint16_t)seq;
    ack.encrypt = 0;
    ack.buf = n ? value : 0;
    ack.length = (uint32_t)n;
    int r = (a.api->*get(AckInterfaceM()))(&ack);
    if (r != 0 && n > PRO_PURE_DATA_MAX_SIZE)
      okit_error(req, "impossible_length", "ackInterface refuses a value over PRO_PURE_DATA_MAX_SIZE");
    else if (r == 0 && g_sent.empty() && session == 0)
      okit_error(req, "bad_session", "ackInterface sends nothing in session 0");
    else if (r != 0 || g_sent.empty())
      // a valid ACK the SDK will not send (allocACK finds no room in its memory pool)
      okit_error(req, "internal_error", "the SDK's ackInterface refused to send this ACK (returned -1)");
    else {
      osdk_json_t *w = okit_result(req, 2 * g_sent.size() + 64);
      if (w) {
        osdk_json_begin_object(w);
        osdk_json_key(w, "hex");
        osdk_json_hex(w, &g_sent[0], g_sent.size());
        osdk_json_end_object(w);
      }
    }
  } else {
    // a command as CoreAPI::send lays it out (set, id, value), with sendInterface's length
    // check, framed by the SDK's encrypt() with the session and SEQ asked for
    std::vector<uint8_t> cmd(n + 2);
    cmd[0] = (uint8_t)set;
    cmd[1] = (uint8_t)id;
    if (n) memcpy(&cmd[2], value, n);
    if (cmd.size() > PRO_PURE_DATA_MAX_SIZE) {
      okit_error(req, "impossible_length", "sendInterface refuses a value over PRO_PURE_DATA_MAX_SIZE");
    } else {
      std::vector<uint8_t> frame(cmd.size() + 16);   // what the SDK allocates for it (calculateLength)
      unsigned short len = (a.api->*get(EncryptM()))(&frame[0], &cmd[0], (unsigned short)cmd.size(), 0, 0,
                                                    (unsigned char)session, (unsigned short)seq);
      if (len == 0 || len > frame.size()) {
        okit_error(req, "internal_error", "adapter: encrypt() built no frame");
      } else {
        osdk_json_t *w = okit_result(req, 2 * len + 64);
        if (w) {
          osdk_json_begin_object(w);
          osdk_json_key(w, "hex");
          osdk_json_hex(w, &frame[0], len);
          osdk_json_end_object(w);
        }
      }
    }
  }
  free(value);
}

}  // namespace

int main(int argc, char **argv) {
  size_t k = 0;
  for (size_t i = 0; i < 3; i++)
    if (OSDKC_CORE_PROFILES >> i & 1) {
      g_profile_ids[k] = ALL_PROFILES[i].id;
      g_profile_of[k] = ALL_PROFILES[i].p;
      k++;
    }
  g_profile_ids[k] = 0;
  okit_testee t;
  memset(&t, 0, sizeof t);
  static char name[64];
  snprintf(name, sizeof name, "DJI Onboard-SDK core %d", OSDKC_CORE_VERSION);
  t.name = name;
  t.profiles = g_profile_ids;
  t.decode_stream = decode_stream;
  t.decode_frame = decode_frame;
  t.decode_payload = decode_payload;
  t.encode_frame = encode_frame;
  return okit_main(&t, argc, argv);
}
