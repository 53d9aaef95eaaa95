// osdkc sdk host-test: a host program built on DJI Onboard-SDK 2.3 (lib/ layout).
//
// 2.3's lib/ has no serial driver of its own; a Linux user program takes the
// one of the release's command-line sample (HardDriverManifold,
// sample/commandline/Linux/conboardSDK/), which host.py compiles unchanged
// from the user's tree. Beyond that driver only the SDK's public API is used
// (CoreAPI, Flight, the CallBack interface), and the session is the one of
// driver31.cpp: version, activation with key, broadcast frequencies, the
// broadcast as the SDK decoded it, obtain control, movement control, release,
// frequency restore. Output: the JSON lines of driver31.cpp ("open", "step",
// "bc", "log", "done"); the frequency steps carry "sdk_ok" (the ACK the SDK's
// callback got means success; null when none came within 2 s) next to our "ok".
//
// 2.3 chooses its protocol at compile time: DJI_Config.h defines
// SDK_VERSION_2_3 (FW 2.3: 4-byte time stamp, 12-byte gimbal, one-byte control
// info, a version reply without ID) or SDK_VERSION_3_1_M100; the activation
// carries DJI_Version.h's SDK_VERSION for it. --sdk-version must equal it.
//
// CoreAPI::setBroadcastFreq rewrites the caller's 16 codes in place before it
// sends them; the frequencies steps report the codes it sent, fail when they
// are not the ones asked for, and then send the asked codes with the SDK's
// public CoreAPI::send (the frequency command, set 0x00 id 0x10) so that the
// rest of the session can still be measured. The detail says so.
//
// SIGINT/SIGTERM: the session stops at the next step and still releases
// control and restores the frequencies before exiting.

#include <DJI_API.h>
#include <DJI_Flight.h>
#include <DJIHardDriverManifold.h>

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

// The sample's serial driver as shipped; only its log sink (HardDriver::displayLog)
// is redirected into the JSON stream.
class LoggingSerial : public HardDriverManifold {
 public:
  LoggingSerial(const std::string &port, unsigned baud) : HardDriverManifold(port, baud) {}
  void displayLog(char *buf = 0) override {
    std::string text = buf ? buf : DJI::onboardSDK::buffer;
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    emit("{\"ev\":\"log\",\"text\":" + json_string(text) + "}");
  }
};

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

// The ACK value follows the frame header; its first two bytes are the return
// code of every command used here.
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
  CoreAPI::getVersionCallback(api, header, data);   // the SDK's own reading (it logs the name)
  record_ack(header, data);
}

void on_activate(CoreAPI *api, Header *header, UserData data) {
  CoreAPI::activateCallback(api, header, data);      // on success the SDK installs the key
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
  std::mutex m;
  volatile bool record = false;
  long broadcasts = 0;
  BroadcastData last{};
};

// The onboard device in control: CtrlInfoData.device, "2->serial" (DJI_Type.h).
const unsigned DEVICE_ONBOARD = 2;

// Every broadcast, named in the spec's vocabulary from the SDK's decoded structure.
void on_broadcast(CoreAPI *api, Header *header, UserData data) {
  Session *s = static_cast<Session *>(data);
  if (!s->record) return;
  BroadcastData b = api->getBroadcastData();
  Fields f;
#ifdef SDK_VERSION_2_3
  f.add("time_stamp.time", b.timeStamp);
#else
  f.add("time_stamp.time", b.timeStamp.time);
  f.add("time_stamp.nano_time", b.timeStamp.nanoTime);
  f.add("time_stamp.sync_flag", b.timeStamp.syncFlag);
#endif
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
#ifndef SDK_VERSION_2_3
  f.add("gimbal.limit.pitch_limit", b.gimbal.pitchLimit);
  f.add("gimbal.limit.roll_limit", b.gimbal.rollLimit);
  f.add("gimbal.limit.yaw_limit", b.gimbal.yawLimit);
  f.add("gimbal.limit.reserved", b.gimbal.reserved);
  f.add("control_info.cur_mov_control_mode", b.ctrlInfo.data);
#endif
  f.add("flight_status", b.status);
  f.add("battery", b.battery);
  // 2.3 names the device byte's bits 0-2 device, bit 3 signature and bits 4-7
  // reserved; the spec's virtual_rc is the lowest of those four.
  f.add("control_info.control_device", b.ctrlInfo.device);
  f.add("control_info.onboard_requested", b.ctrlInfo.signature);
  f.add("control_info.virtual_rc", b.ctrlInfo.reserved & 1);
  f.add("control_info.reserved", b.ctrlInfo.reserved >> 1);
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
  std::vector<int> restore;
  Version sdk_version = 0;
  size_t items = 0;
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
    while (t->run) t->api->readPoll();   // the sample driver's read returns once its buffer is full
    return 0;
  }
  static void *send_loop(void *p) {
    Threads *t = static_cast<Threads *>(p);
    while (t->run) {
      t->api->sendPoll();
      usleep(5000);
    }
    return 0;
  }
  void start() {
    pthread_create(&reader, 0, read_loop, this);
    pthread_create(&sender, 0, send_loop, this);
  }
  void stop() {
    run = false;
    pthread_join(sender, 0);
  }
};

const double ACK_TIMEOUT_S = 2.0;
const unsigned NO_ACK = 0x10000u;   // no ACK came: outside the 16-bit codes

std::string code_text(const Pending &p) {
  char buf[64];
  snprintf(buf, sizeof buf, "ACK code 0x%04X (%zu byte value)", p.code, p.length);
  return buf;
}

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

std::string code_list(const uint8_t *codes, size_t n) {
  std::string out;
  for (size_t i = 0; i < n; i++) out += (i ? "," : "") + std::to_string(codes[i]);
  return out;
}

// setBroadcastFreq with the codes asked for; the step passes when the SDK sent
// them and the flight controller acknowledged with 0. `sdk_ok` is the ACK's
// verdict alone. When the SDK sent other codes, the asked ones go out once more
// through CoreAPI::send so that the session can go on.
// Both commands have Pendings of their own that outlive the call: an ACK that
// comes late (the sample driver's read returns only once its buffer is full,
// and with every rate at 0 Hz the line is quiet) must not complete a later step.
bool set_frequencies(CoreAPI &api, const std::vector<int> &codes, size_t items, std::string &detail,
                     bool &sdk_ok, unsigned &sdk_code) {
  static Pending p, again;
  uint8_t asked[16] = {0}, freq[16] = {0};
  for (size_t i = 0; i < codes.size() && i < 16; i++) asked[i] = freq[i] = static_cast<uint8_t>(codes[i]);
  p.reset();
  api.setBroadcastFreq(freq, on_ack, &p);   // 2.3 rewrites freq in place before sending it
  bool acked = p.wait(ACK_TIMEOUT_S);
  sdk_ok = acked && p.code == 0;
  sdk_code = acked ? p.code : NO_ACK;
  detail = acked ? code_text(p) : "no ACK within 2 s";
  bool same = memcmp(asked, freq, items) == 0;
  if (same) return sdk_ok;
  detail += "; CoreAPI::setBroadcastFreq sent codes " + code_list(freq, items) + " for the codes asked, " +
            code_list(asked, items);
  again.reset();
  api.send(2, false, SET_ACTIVATION, CODE_FREQUENCY, asked, 16, 100, 1, on_ack, &again);
  detail += "; the asked codes sent with CoreAPI::send: " +
            (again.wait(ACK_TIMEOUT_S) ? code_text(again) : std::string("no ACK within 2 s"));
  return false;
}

// The SDK's verdict on a frequency command: none (null, no code) when no ACK
// reached the caller in time.
std::string sdk_verdict(bool sdk_ok, unsigned sdk_code) {
  if (sdk_code == NO_ACK) return ",\"sdk_ok\":null";
  return std::string(",\"sdk_ok\":") + (sdk_ok ? "true" : "false") + ",\"sdk_code\":" + std::to_string(sdk_code);
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
  if (o.sdk_version != SDK_VERSION) {
    char text[160];
    snprintf(text, sizeof text, "the tree is built for SDK version 0x%08X (DJI_Config.h), the profile needs 0x%08X",
             static_cast<unsigned>(SDK_VERSION), static_cast<unsigned>(o.sdk_version));
    step("open", false, text);
    emit("{\"ev\":\"done\",\"ok\":false}");
    return 1;
  }
  // HardDriverManifold::init reports a port it cannot open only in its log
  if (access(o.port.c_str(), R_OK | W_OK) != 0) {
    step("open", false, "the SDK's serial driver could not open " + o.port);
    emit("{\"ev\":\"done\",\"ok\":false}");
    return 1;
  }

  const size_t items = o.items;
  DJI::onboardSDK::encrypt = static_cast<uint8_t>(o.encrypt);
  LoggingSerial serial(o.port, o.baud);
  serial.init();
  CoreAPI api(&serial, false);
  Session session;
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
  api.getVersion(on_version, &p);
  bool ok = p.wait(ACK_TIMEOUT_S);
  step("version", ok, ok ? code_text(p) : "no ACK within 2 s",
       ",\"value_length\":" + std::to_string(p.length) + ",\"sdk_code\":" + std::to_string(p.code));
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

  bool sdk_ok = false;
  unsigned sdk_code = 0;
  if (!g_stop) {
    ok = set_frequencies(api, std::vector<int>(items, BROADCAST_FREQ_50HZ), items, detail, sdk_ok, sdk_code);
    frequencies_set = true;
    step("frequencies", ok, detail, sdk_verdict(sdk_ok, sdk_code));
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

  if (!g_stop) {
    ok = set_control(api, true, p, detail);
    in_control = ok;
    step("obtain_control", ok, detail, ",\"sdk_code\":" + std::to_string(p.code));
    all_ok &= ok;
  }
  if (!g_stop && in_control) {
    Flight flight(&api);
    const uint8_t flag = Flight::HORIZONTAL_VELOCITY | Flight::VERTICAL_VELOCITY | Flight::YAW_PALSTANCE |
                         Flight::HORIZONTAL_GROUND | Flight::SMOOTH_ENABLE;
    const float vx = 2.0f, vy = 1.0f, vz = 0.5f, yaw_rate = 10.0f;
    FlightData command;
    command.flag = flag;
    command.x = vx;
    command.y = vy;
    command.z = vz;
    command.yaw = yaw_rate;
    int sent = 0;
    for (; sent < o.moves && !g_stop; sent++) {
      flight.setFlight(&command);
      usleep(20000);
    }
    BroadcastData b;
    {
      std::lock_guard<std::mutex> lock(session.m);
      b = session.last;
    }
    bool follows = std::abs(b.v.x - vx) < 0.1f * vx && std::abs(b.v.y - vy) < 0.1f * vy &&
                   std::abs(b.v.z - vz) < 0.1f * vz && b.ctrlInfo.device == DEVICE_ONBOARD;
    char text[200];
    snprintf(text, sizeof text, "%d commands (flag 0x%02X, %.1f %.1f %.1f m/s, %.0f deg/s); SDK reads velocity "
             "%.3f %.3f %.3f, device %u", sent, flag, vx, vy, vz, yaw_rate, b.v.x, b.v.y, b.v.z,
             static_cast<unsigned>(b.ctrlInfo.device));
    std::string extra = ",\"sent\":" + std::to_string(sent) + ",\"flag\":" + std::to_string(flag);
#ifndef SDK_VERSION_2_3
    extra += ",\"mode\":" + std::to_string(b.ctrlInfo.data);   // FW 3.1: the movement mode byte
#endif
    ok = follows && sent == o.moves;
    step("movement", ok, text, extra);
    all_ok &= ok;
  }

  if (in_control) {
    ok = set_control(api, false, p, detail);
    step("release_control", ok, detail, ",\"sdk_code\":" + std::to_string(p.code));
    all_ok &= ok;
  }
  if (frequencies_set && !o.restore.empty()) {
    ok = set_frequencies(api, o.restore, items, detail, sdk_ok, sdk_code);
    step("frequency_restore", ok, detail, sdk_verdict(sdk_ok, sdk_code));
    all_ok &= ok;
  }
  threads.stop();
  all_ok &= !g_stop;
  emit(std::string("{\"ev\":\"done\",\"ok\":") + (all_ok ? "true" : "false") +
       ",\"interrupted\":" + (g_stop ? "true" : "false") + "}");
  _exit(all_ok ? 0 : 1);
}
