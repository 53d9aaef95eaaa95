// osdkc sdk host-test: a host program built on DJI Onboard-SDK 3.1.x.
//
// It uses the SDK's public API only (CoreAPI, Flight, the LinuxSerialDevice
// driver, the documented CallBack interface) and runs one session against a
// flight controller: version, activation with key, broadcast frequencies,
// obtain control, movement control, release, frequency restore. It prints one
// JSON object per line on stdout:
//   {"ev":"open", ...}                    the port is open (the harness then starts the broadcast)
//   {"ev":"step","step":S,"ok":B,...}    the outcome of one step, as the SDK saw it
//   {"ev":"bc","seq":N,"flags":F,"f":{}} one broadcast as the SDK decoded it; float
//                                         fields are printed as their IEEE bits
//   {"ev":"log","text":T}                 a log line of the SDK (its HardDriver::displayLog)
//   {"ev":"done","ok":B}
// The SDK's blocking calls report a timeout as success and its retry timer
// counts seconds as milliseconds, so every command here uses the callback API
// and waits for the ACK with a deadline of its own.
//
// --encrypt 0|1 sets the SDK's public switch DJI::onboardSDK::encrypt (DJI_Type.h;
// DJI_Config.h's USE_ENCRYPT makes it 1 by default): control and movement
// commands go out encrypted or plain. Broadcasts are reported from the
// activation on (before it an encrypting aircraft's frames cannot be read).
//
// 3.2.x: the same core and serial driver. 3.2.0 still takes the SDK version
// from the caller. 3.2.1 and 3.2.2 (OSDKC_FW_FROM_AIRCRAFT, set by host.py when
// DJI_API.h declares getFwVersion) take no version: CoreAPI parses hardware,
// firmware and serial number out of the version reply, and activation carries
// that firmware word. Their getDroneVersionCallback logs nothing, so the version
// step reports what the public getters read (getHwSerialNum, getHwVersion,
// getFwVersion).
//
// SIGINT/SIGTERM: the session stops at the next step and still releases
// control and restores the frequencies before exiting.

#include <DJI_API.h>
#include <DJI_Flight.h>
#include <LinuxSerialDevice.h>

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

using namespace DJI::onboardSDK;
using DJI::UserData;

namespace {

volatile sig_atomic_t g_stop = 0;
std::mutex g_out;

void on_signal(int) { g_stop = 1; }

std::string json_string(const std::string &s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || c >= 0x7f) {
      char esc[8];
      snprintf(esc, sizeof esc, "\\u%04x", c);
      out += esc;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

void emit(const std::string &line) {
  std::lock_guard<std::mutex> lock(g_out);
  fputs(line.c_str(), stdout);
  fputc('\n', stdout);
  fflush(stdout);
}

// The Linux serial driver as shipped; only its log sink is redirected into
// the JSON stream, so the harness sees what the SDK reported.
class LoggingSerial : public LinuxSerialDevice {
 public:
  LoggingSerial(const std::string &port, unsigned baud) : LinuxSerialDevice(port, baud) {}
  void displayLog(const char *buf = 0) override {
    std::string text = buf ? buf : DJI::onboardSDK::buffer;
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    emit("{\"ev\":\"log\",\"text\":" + json_string(text) + "}");
  }
};

// One outstanding command: the callback fills it, the main thread waits.
struct Pending {
  std::mutex m;
  std::condition_variable cv;
  bool done = false;
  unsigned code = 0;
  size_t length = 0;
  void reset() {
    std::lock_guard<std::mutex> lock(m);
    done = false;
    code = 0;
    length = 0;
  }
  bool wait(double seconds) {
    std::unique_lock<std::mutex> lock(m);
    return cv.wait_for(lock, std::chrono::milliseconds(static_cast<long>(seconds * 1000)),
                       [this] { return done; });
  }
};

// The ACK value follows the frame header (the CallBack contract); its first
// two bytes are the return code of every command used here.
void record_ack(Header *header, UserData data) {
  Pending *p = static_cast<Pending *>(data);
  const unsigned char *value = reinterpret_cast<unsigned char *>(header) + sizeof(Header);
  size_t length = header->length - EXC_DATA_SIZE;
  std::lock_guard<std::mutex> lock(p->m);
  p->length = length;
  p->code = length >= 2 ? value[0] | value[1] << 8 : length == 1 ? value[0] : 0xFFFFu;
  p->done = true;
  p->cv.notify_all();
}

void on_ack(CoreAPI *, Header *header, UserData data) { record_ack(header, data); }

void on_version(CoreAPI *api, Header *header, UserData data) {
  CoreAPI::getDroneVersionCallback(api, header, data);   // the SDK's own reading (it logs ID and name)
  record_ack(header, data);
}

void on_activate(CoreAPI *api, Header *header, UserData data) {
  CoreAPI::activateCallback(api, header, data);           // on success the SDK installs the key
  record_ack(header, data);
}

std::string bits32(float f) {
  uint32_t u;
  memcpy(&u, &f, 4);
  return std::to_string(u);
}

std::string bits64(double d) {
  uint64_t u;
  memcpy(&u, &d, 8);
  return std::to_string(u);
}

struct Fields {
  std::ostringstream s;
  bool first = true;
  void add(const char *name, const std::string &value) {
    s << (first ? "" : ",") << '"' << name << "\":" << value;
    first = false;
  }
  void add(const char *name, long long value) { add(name, std::to_string(value)); }
};

struct Session {
  CoreAPI *api;
  std::mutex m;
  volatile bool record = false;
  long broadcasts = 0;
  BroadcastData last{};
};

// Every broadcast, named in the spec's vocabulary from the SDK's decoded structure.
void on_broadcast(CoreAPI *api, Header *header, UserData data) {
  Session *s = static_cast<Session *>(data);
  if (!s->record) return;
  BroadcastData b = api->getBroadcastData();
  Fields f;
  f.add("time_stamp.time", b.timeStamp.time);
  f.add("time_stamp.nano_time", b.timeStamp.nanoTime);
  f.add("time_stamp.sync_flag", b.timeStamp.syncFlag);
  f.add("quaternion.q0", bits32(b.q.q0));
  f.add("quaternion.q1", bits32(b.q.q1));
  f.add("quaternion.q2", bits32(b.q.q2));
  f.add("quaternion.q3", bits32(b.q.q3));
  f.add("acceleration.x", bits32(b.a.x));
  f.add("acceleration.y", bits32(b.a.y));
  f.add("acceleration.z", bits32(b.a.z));
  f.add("velocity.x", bits32(b.v.x));
  f.add("velocity.y", bits32(b.v.y));
  f.add("velocity.z", bits32(b.v.z));
  f.add("velocity.data_valid", b.v.health);
  f.add("velocity.sensor_id", b.v.sensorID);
  f.add("velocity.reserved", b.v.reserve);
  f.add("angular_rate.x", bits32(b.w.x));
  f.add("angular_rate.y", bits32(b.w.y));
  f.add("angular_rate.z", bits32(b.w.z));
  f.add("position.latitude", bits64(b.pos.latitude));
  f.add("position.longitude", bits64(b.pos.longitude));
  f.add("position.altitude", bits32(b.pos.altitude));
  f.add("position.height", bits32(b.pos.height));
  f.add("position.gps_health", b.pos.health);
  f.add("gps_detail.date", b.gps.date);
  f.add("gps_detail.time", b.gps.time);
  f.add("gps_detail.longitude", b.gps.longitude);
  f.add("gps_detail.latitude", b.gps.latitude);
  f.add("gps_detail.height_msl", b.gps.Hmsl);
  f.add("gps_detail.vel_n", bits32(b.gps.velocityNorth));
  f.add("gps_detail.vel_e", bits32(b.gps.velocityEast));
  f.add("gps_detail.vel_d", bits32(b.gps.velocityGround));
  f.add("rtk_detail.date", b.rtk.date);
  f.add("rtk_detail.time", b.rtk.time);
  f.add("rtk_detail.longitude", bits64(b.rtk.longitude));
  f.add("rtk_detail.latitude", bits64(b.rtk.latitude));
  f.add("rtk_detail.height_msl", bits32(b.rtk.Hmsl));
  f.add("rtk_detail.vel_n", bits32(b.rtk.velocityNorth));
  f.add("rtk_detail.vel_e", bits32(b.rtk.velocityEast));
  f.add("rtk_detail.vel_d", bits32(b.rtk.velocityGround));
  f.add("rtk_detail.yaw", b.rtk.yaw);
  f.add("rtk_detail.position_flag", b.rtk.posFlag);
  f.add("rtk_detail.yaw_flag", b.rtk.yawFlag);
  f.add("magnetometer.x", b.mag.x);
  f.add("magnetometer.y", b.mag.y);
  f.add("magnetometer.z", b.mag.z);
  f.add("rc.roll", b.rc.roll);
  f.add("rc.pitch", b.rc.pitch);
  f.add("rc.yaw", b.rc.yaw);
  f.add("rc.throttle", b.rc.throttle);
  f.add("rc.mode", b.rc.mode);
  f.add("rc.gear", b.rc.gear);
  f.add("gimbal.roll", bits32(b.gimbal.roll));
  f.add("gimbal.pitch", bits32(b.gimbal.pitch));
  f.add("gimbal.yaw", bits32(b.gimbal.yaw));
  f.add("gimbal.limit.pitch_limit", b.gimbal.pitchLimit);
  f.add("gimbal.limit.roll_limit", b.gimbal.rollLimit);
  f.add("gimbal.limit.yaw_limit", b.gimbal.yawLimit);
  f.add("gimbal.limit.reserved", b.gimbal.reserved);
  f.add("flight_status", b.status);
  f.add("battery", b.battery);
  f.add("control_info.cur_mov_control_mode", b.ctrlInfo.mode);
  f.add("control_info.control_device", b.ctrlInfo.deviceStatus);
  f.add("control_info.onboard_requested", b.ctrlInfo.flightStatus);
  f.add("control_info.virtual_rc", b.ctrlInfo.vrcStatus);
  f.add("control_info.reserved", b.ctrlInfo.reserved);
  emit("{\"ev\":\"bc\",\"seq\":" + std::to_string(header->sequenceNumber) + ",\"flags\":" +
       std::to_string(b.dataFlag) + ",\"f\":{" + f.s.str() + "}}");
  std::lock_guard<std::mutex> lock(s->m);
  s->broadcasts++;
  s->last = b;
}

struct Options {
  std::string port, key_env;
  unsigned baud = 230400;
  unsigned app_id = 0;
  long frames = 500;
  int moves = 150;
  int encrypt = 0;
  std::vector<int> restore;   // frequency codes to restore at the end, one per item
  Version sdk_version = 0;    // the SDK target version of the profile (rules.yaml covers.sdk_version)
  size_t items = 0;           // how many items the profile's flag word has
};

std::vector<int> parse_codes(const char *text) {
  std::vector<int> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(atoi(item.c_str()));
  return out;
}

bool parse(int argc, char **argv, Options &o) {
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string k = argv[i];
    const char *v = argv[i + 1];
    if (k == "--port") o.port = v;
    else if (k == "--baud") o.baud = static_cast<unsigned>(atol(v));
    else if (k == "--sdk-version") o.sdk_version = static_cast<Version>(strtoul(v, 0, 0));
    else if (k == "--items") o.items = static_cast<size_t>(atol(v));
    else if (k == "--app-id") o.app_id = static_cast<unsigned>(atol(v));
    else if (k == "--key-env") o.key_env = v;
    else if (k == "--frames") o.frames = atol(v);
    else if (k == "--moves") o.moves = atoi(v);
    else if (k == "--restore") o.restore = parse_codes(v);
    else if (k == "--encrypt") o.encrypt = atoi(v) != 0;
    else return false;
  }
  // the profile is the caller's business: it passes what the SDK and the broadcast need of it
  return !o.port.empty() && o.sdk_version != 0 && o.items >= 1 && o.items <= 16 && !o.key_env.empty();
}

void step(const char *name, bool ok, const std::string &detail, const std::string &extra = "") {
  emit(std::string("{\"ev\":\"step\",\"step\":\"") + name + "\",\"ok\":" + (ok ? "true" : "false") +
       ",\"detail\":" + json_string(detail) + extra + "}");
}

struct Threads {
  CoreAPI *api;
  volatile bool run = true;
  pthread_t reader{}, sender{};
  static void *read_loop(void *p) {
    Threads *t = static_cast<Threads *>(p);
    while (t->run) t->api->readPoll();   // the driver's read blocks for at most 0.1 s (VTIME)
    return 0;
  }
  static void *send_loop(void *p) {
    Threads *t = static_cast<Threads *>(p);
    while (t->run) {
      t->api->sendPoll();                  // retransmissions; new frames are written by send()
      usleep(5000);
    }
    return 0;
  }
  void start() {
    pthread_create(&reader, 0, read_loop, this);
    pthread_create(&sender, 0, send_loop, this);
  }
  // The reader may sit in a blocking read (VMIN) for good if the line goes
  // quiet: it is not joined, the process ends with _exit.
  void stop() {
    run = false;
    pthread_join(sender, 0);
  }
};

const double ACK_TIMEOUT_S = 2.0;

std::string code_text(const Pending &p) {
  char buf[64];
  snprintf(buf, sizeof buf, "ACK code 0x%04X (%zu byte value)", p.code, p.length);
  return buf;
}

// setControl, repeated while the flight controller answers "in progress".
bool set_control(CoreAPI &api, bool obtain, Pending &p, std::string &detail) {
  const unsigned want = obtain ? ACK_SETCONTROL_OBTAIN_SUCCESS : ACK_SETCONTROL_RELEASE_SUCCESS;
  const unsigned running = obtain ? ACK_SETCONTROL_OBTAIN_RUNNING : ACK_SETCONTROL_RELEASE_RUNNING;
  std::string codes;
  p.code = 0xFFFFu;
  for (int attempt = 0; attempt < 5; attempt++) {
    p.reset();
    api.setControl(obtain, on_ack, &p);
    if (!p.wait(ACK_TIMEOUT_S)) {
      detail = "no ACK within 2 s" + (codes.empty() ? "" : " after " + codes);
      return false;
    }
    char c[16];
    snprintf(c, sizeof c, "%s0x%04X", codes.empty() ? "" : ", ", p.code);
    codes += c;
    if (p.code == want) {
      detail = "ACK codes " + codes;
      return true;
    }
    if (p.code != running) break;
  }
  detail = "ACK codes " + codes;
  return false;
}

bool set_frequencies(CoreAPI &api, const std::vector<int> &codes, Pending &p, std::string &detail) {
  uint8_t freq[16] = {0};
  for (size_t i = 0; i < codes.size() && i < 16; i++) freq[i] = static_cast<uint8_t>(codes[i]);
  p.reset();
  api.setBroadcastFreq(freq, on_ack, &p);
  if (!p.wait(ACK_TIMEOUT_S)) {
    detail = "no ACK within 2 s";
    return false;
  }
  detail = code_text(p);
  return p.code == 0;
}

}  // namespace

int main(int argc, char **argv) {
  Options o;
  if (!parse(argc, argv, o)) {
    fprintf(stderr, "usage: %s --port PATH --sdk-version N --items N --key-env VAR [--baud B] "
                    "[--app-id N] [--frames N] [--moves N] [--restore C,C,...] [--encrypt 0|1]\n", argv[0]);
    return 2;
  }
  const char *key = getenv(o.key_env.c_str());
  if (!key) {
    fprintf(stderr, "environment variable %s is not set\n", o.key_env.c_str());
    return 2;
  }
  std::string key_text = key;
  signal(SIGINT, on_signal);
  signal(SIGTERM, on_signal);

  const size_t items = o.items;
  DJI::onboardSDK::encrypt = static_cast<uint8_t>(o.encrypt);
  LoggingSerial serial(o.port, o.baud);
  serial.init();
#ifndef OSDKC_INIT_SETS_NO_STATUS   // 3.1.8's init() leaves the status unset; the version step shows a dead port
  if (!serial.getDeviceStatus()) {
    step("open", false, "the SDK's serial driver could not open " + o.port);
    emit("{\"ev\":\"done\",\"ok\":false}");
    return 1;
  }
#endif
#ifdef OSDKC_FW_FROM_AIRCRAFT
  CoreAPI api(&serial, false);   // the version comes from the aircraft's version reply
#else
  CoreAPI api(&serial, o.sdk_version, false);
#endif
  Session session;
  session.api = &api;
  api.setBroadcastCallback(on_broadcast, &session);
  Threads threads;
  threads.api = &api;
  threads.start();
  emit("{\"ev\":\"open\",\"port\":" + json_string(o.port) + ",\"baud\":" + std::to_string(o.baud) + "}");

  Pending p;
  bool all_ok = true, in_control = false, frequencies_set = false;
  std::string detail;

  // version
  p.reset();
  api.getDroneVersion(on_version, &p);
  bool ok = p.wait(ACK_TIMEOUT_S);
  std::string read_back;
#ifdef OSDKC_FW_FROM_AIRCRAFT
  if (ok) {
    // what the SDK made of the reply: ID, hardware and firmware (0 when it could not parse it)
    char fw[16];
    snprintf(fw, sizeof fw, "%u", static_cast<unsigned>(api.getFwVersion()));
    read_back = ",\"version_id\":" + json_string(std::string(api.getHwSerialNum(), strnlen(api.getHwSerialNum(), 16))) +
                ",\"hw_version\":" + json_string(std::string(api.getHwVersion(), strnlen(api.getHwVersion(), 12))) +
                ",\"fw_version\":" + fw;
  }
#endif
  step("version", ok, ok ? code_text(p) : "no ACK within 2 s",
       ",\"value_length\":" + std::to_string(p.length) + ",\"sdk_code\":" + std::to_string(p.code) + read_back);
  all_ok &= ok;

  // activation with the app id and key
  if (!g_stop) {
    ActivateData data;
    memset(&data, 0, sizeof data);
    data.ID = o.app_id;
    data.encKey = &key_text[0];
    p.reset();
    session.record = true;
    api.activate(&data, on_activate, &p);
    ok = p.wait(ACK_TIMEOUT_S) && p.code == ACK_ACTIVE_SUCCESS;
    step("activation", ok, p.done ? code_text(p) : "no ACK within 2 s", ",\"sdk_code\":" + std::to_string(p.code));
    all_ok &= ok;
  }

  // every item at 50 Hz, then the broadcast as the SDK decodes it
  if (!g_stop) {
    ok = set_frequencies(api, std::vector<int>(items, BROADCAST_FREQ_50HZ), p, detail);
    frequencies_set = true;
    step("frequencies", ok, detail, ",\"sdk_code\":" + std::to_string(p.code));
    all_ok &= ok;
  }
  if (!g_stop) {
    long start;
    {
      std::lock_guard<std::mutex> lock(session.m);
      start = session.broadcasts;
    }
    auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(o.frames * 20 * 3 + 2000);
    long got = 0;
    while (!g_stop && std::chrono::steady_clock::now() < deadline) {
      {
        std::lock_guard<std::mutex> lock(session.m);
        got = session.broadcasts - start;
      }
      if (got >= o.frames) break;
      usleep(20000);
    }
    ok = got >= o.frames;
    step("broadcast", ok, std::to_string(got) + " broadcasts decoded by the SDK after the frequency change",
         ",\"frames\":" + std::to_string(got));
    all_ok &= ok;
  }

  // obtain control, movement control, release
  if (!g_stop) {
    ok = set_control(api, true, p, detail);
    in_control = ok;
    step("obtain_control", ok, detail, ",\"sdk_code\":" + std::to_string(p.code));
    all_ok &= ok;
  }
  if (!g_stop && in_control) {
    Flight flight(&api);
    const uint8_t flag = Flight::HORIZONTAL_VELOCITY | Flight::VERTICAL_VELOCITY | Flight::YAW_RATE |
                         Flight::HORIZONTAL_GROUND | Flight::SMOOTH_ENABLE;
    const float vx = 2.0f, vy = 1.0f, vz = 0.5f, yaw_rate = 10.0f;
    int sent = 0;
    for (; sent < o.moves && !g_stop; sent++) {
      flight.setMovementControl(flag, vx, vy, vz, yaw_rate);
      usleep(20000);
    }
    BroadcastData b;
    {
      std::lock_guard<std::mutex> lock(session.m);
      b = session.last;
    }
    // The vehicle follows when the SDK reads back the commanded velocity, the
    // onboard device in control and the matching movement mode.
    bool follows = std::abs(b.v.x - vx) < 0.1f * vx && std::abs(b.v.y - vy) < 0.1f * vy &&
                   std::abs(b.v.z - vz) < 0.1f * vz && b.ctrlInfo.deviceStatus == Flight::DEVICE_SDK &&
                   b.ctrlInfo.mode == Flight::HORIZ_VEL_VERT_VEL_YAW_RATE;
    char text[200];
    snprintf(text, sizeof text, "%d commands (flag 0x%02X, %.1f %.1f %.1f m/s, %.0f deg/s); SDK reads velocity "
             "%.3f %.3f %.3f, device %u, mode %u", sent, flag, vx, vy, vz, yaw_rate, b.v.x, b.v.y, b.v.z,
             b.ctrlInfo.deviceStatus, b.ctrlInfo.mode);
    ok = follows && sent == o.moves;
    step("movement", ok, text, ",\"sent\":" + std::to_string(sent) + ",\"flag\":" + std::to_string(flag) +
         ",\"mode\":" + std::to_string(b.ctrlInfo.mode));
    all_ok &= ok;
  }

  // Whatever happened above, hand control back and restore the frequencies.
  if (in_control) {
    ok = set_control(api, false, p, detail);
    step("release_control", ok, detail, ",\"sdk_code\":" + std::to_string(p.code));
    all_ok &= ok;
  }
  if (frequencies_set && !o.restore.empty()) {
    ok = set_frequencies(api, o.restore, p, detail);
    step("frequency_restore", ok, detail, ",\"sdk_code\":" + std::to_string(p.code));
    all_ok &= ok;
  }
  threads.stop();
  all_ok &= !g_stop;
  emit(std::string("{\"ev\":\"done\",\"ok\":") + (all_ok ? "true" : "false") +
       ",\"interrupted\":" + (g_stop ? "true" : "false") + "}");
  _exit(all_ok ? 0 : 1);
}
