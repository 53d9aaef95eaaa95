// osdkc sdk host-test: a host program built on DJI Onboard-SDK 3.3 to 3.9.
//
// It uses the SDK's public Vehicle API only, as a user program does: a
// Vehicle on the port (the tree's own Linux serial driver and POSIX threads),
// the version query, activation with app id and key, broadcast frequencies,
// the broadcast as the SDK decoded it (DataBroadcast getters, read in the
// user broadcast callback), obtain control, movement control at 50 Hz,
// release, frequency restore. The blocking calls are used, as DJI's samples
// do. Output: the JSON lines of driver31.cpp ("open", "step", "bc", "log",
// "done"), and:
//   {"ev":"fields","names":[...]}  the spec fields the public API exposes (once)
//   step events carry "sdk_ok" (the SDK's own verdict, ACK::getError) and
//   "sdk_code" (the ACK code as the SDK stored it) next to our "ok".
// The SDK logs with printf on stdout: stdout is a pipe read back here and
// turned into "log" events, so SDK output never splits a JSON line.
//
// Build-time knowledge of the release (a define set by host.py):
//   OSDKC_SET_ENCRYPTION  Vehicle::setEncryption exists (3.4 and later);
//                         3.3.x sends every command with a constant
//                         encrypt = 0 (dji_type.hpp) and cannot encrypt.
// 3.3.x runs functionalSetUp (version query, the firmware check, broadcast
// and control set-up) in the constructor, later releases inside activate():
// either way a refused aircraft leaves vehicle->broadcast and ->control null,
// which the activation step reports as "refused".
//
// SIGINT/SIGTERM: the session stops at the next step and still releases
// control and restores the frequencies before exiting.

#include "dji_vehicle.hpp"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

using namespace DJI;
using namespace DJI::OSDK;

namespace {

volatile sig_atomic_t g_stop = 0;
std::mutex g_out;
FILE *g_json = stdout;

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
  fputs(line.c_str(), g_json);
  fputc('\n', g_json);
  fflush(g_json);
}

// The SDK's printf output: every line becomes a "log" event.
void *log_pump(void *arg) {
  FILE *in = fdopen(static_cast<int>(reinterpret_cast<intptr_t>(arg)), "r");
  char line[1024];
  while (in && fgets(line, sizeof line, in)) {
    std::string text = line;
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    if (!text.empty()) emit("{\"ev\":\"log\",\"text\":" + json_string(text) + "}");
  }
  return 0;
}

void capture_sdk_stdout() {
  int json_fd = dup(1);
  int p[2];
  if (json_fd < 0 || pipe(p) != 0) return;
  g_json = fdopen(json_fd, "w");
  dup2(p[1], 1);
  close(p[1]);
  setvbuf(stdout, 0, _IOLBF, 0);
  pthread_t t;
  pthread_create(&t, 0, log_pump, reinterpret_cast<void *>(static_cast<intptr_t>(p[0])));
  pthread_detach(t);
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

// What the public getters expose, in the spec's vocabulary (the M100 layout,
// the one FW 3.1 layout these releases accept; velocity.sensor_id has no getter).
const char *const FIELD_NAMES[] = {
    "time_stamp.time", "time_stamp.nano_time", "time_stamp.sync_flag", "quaternion.q0", "quaternion.q1",
    "quaternion.q2", "quaternion.q3", "acceleration.x", "acceleration.y", "acceleration.z", "velocity.x",
    "velocity.y", "velocity.z", "velocity.data_valid", "velocity.reserved", "angular_rate.x", "angular_rate.y",
    "angular_rate.z", "position.latitude", "position.longitude", "position.altitude", "position.height",
    "position.gps_health", "magnetometer.x", "magnetometer.y", "magnetometer.z", "rc.roll", "rc.pitch", "rc.yaw",
    "rc.throttle", "rc.mode", "rc.gear", "gimbal.roll", "gimbal.pitch", "gimbal.yaw", "gimbal.limit.pitch_limit",
    "gimbal.limit.roll_limit", "gimbal.limit.yaw_limit", "gimbal.limit.reserved", "flight_status", "battery",
    "control_info.cur_mov_control_mode", "control_info.control_device", "control_info.onboard_requested",
    "control_info.virtual_rc", "control_info.reserved"};

struct Session {
  std::mutex m;
  volatile bool record = false;   // from activation on: before it, encrypted frames cannot be read
  long broadcasts = 0;
  Telemetry::Vector3f velocity{};
  Telemetry::SDKInfo info{};
};

Session g_session;

void on_broadcast(Vehicle *vehicle, RecvContainer frame, UserData) {
  if (!g_session.record) return;
  DataBroadcast *b = vehicle->broadcast;
  Telemetry::TimeStamp ts = b->getTimeStamp();
  Telemetry::SyncStamp sync = b->getSyncStamp();
  Telemetry::Quaternion q = b->getQuaternion();
  Telemetry::Vector3f a = b->getAcceleration();
  Telemetry::Vector3f v = b->getVelocity();
  Telemetry::VelocityInfo vi = b->getVelocityInfo();
  Telemetry::Vector3f w = b->getAngularRate();
  Telemetry::GlobalPosition gp = b->getGlobalPosition();
  Telemetry::Mag mag = b->getMag();
  Telemetry::RC rc = b->getRC();
  Telemetry::Gimbal g = b->getGimbal();
  Telemetry::Status st = b->getStatus();
  Telemetry::Battery bat = b->getBatteryInfo();
  Telemetry::SDKInfo info = b->getSDKInfo();
  Fields f;
  f.add("time_stamp.time", ts.time_ms);
  f.add("time_stamp.nano_time", ts.time_ns);
  f.add("time_stamp.sync_flag", sync.flag);
  f.add("quaternion.q0", bits32(q.q0));
  f.add("quaternion.q1", bits32(q.q1));
  f.add("quaternion.q2", bits32(q.q2));
  f.add("quaternion.q3", bits32(q.q3));
  f.add("acceleration.x", bits32(a.x));
  f.add("acceleration.y", bits32(a.y));
  f.add("acceleration.z", bits32(a.z));
  f.add("velocity.x", bits32(v.x));
  f.add("velocity.y", bits32(v.y));
  f.add("velocity.z", bits32(v.z));
  f.add("velocity.data_valid", vi.health);
  f.add("velocity.reserved", vi.reserve);
  f.add("angular_rate.x", bits32(w.x));
  f.add("angular_rate.y", bits32(w.y));
  f.add("angular_rate.z", bits32(w.z));
  f.add("position.latitude", bits64(gp.latitude));
  f.add("position.longitude", bits64(gp.longitude));
  f.add("position.altitude", bits32(gp.altitude));
  f.add("position.height", bits32(gp.height));
  f.add("position.gps_health", gp.health);
  f.add("magnetometer.x", mag.x);
  f.add("magnetometer.y", mag.y);
  f.add("magnetometer.z", mag.z);
  f.add("rc.roll", rc.roll);
  f.add("rc.pitch", rc.pitch);
  f.add("rc.yaw", rc.yaw);
  f.add("rc.throttle", rc.throttle);
  f.add("rc.mode", rc.mode);
  f.add("rc.gear", rc.gear);
  f.add("gimbal.roll", bits32(g.roll));
  f.add("gimbal.pitch", bits32(g.pitch));
  f.add("gimbal.yaw", bits32(g.yaw));
  f.add("gimbal.limit.pitch_limit", g.pitchLimit);
  f.add("gimbal.limit.roll_limit", g.rollLimit);
  f.add("gimbal.limit.yaw_limit", g.yawLimit);
  f.add("gimbal.limit.reserved", g.reserved);
  f.add("flight_status", st.flight);
  f.add("battery", bat.percentage);
  f.add("control_info.cur_mov_control_mode", info.controlMode);
  f.add("control_info.control_device", info.deviceStatus);
  f.add("control_info.onboard_requested", info.flightStatus);
  f.add("control_info.virtual_rc", info.vrcStatus);
  f.add("control_info.reserved", info.reserved);
  // No SEQ: the SDK hands a broadcast the recvInfo of the last ACK (its
  // recvReqData sets no seqNumber, which is 8 bits anyway); the harness
  // matches the frame by its time stamp.
  emit("{\"ev\":\"bc\",\"seq\":null,\"match\":\"time_stamp.time\",\"stale_seq\":" +
       std::to_string(frame.recvInfo.seqNumber) + ",\"flags\":" +
       std::to_string(b->getPassFlag()) + ",\"f\":{" + f.s.str() + "}}");
  std::lock_guard<std::mutex> lock(g_session.m);
  g_session.broadcasts++;
  g_session.velocity = v;
  g_session.info = info;
}

struct Options {
  std::string port, key_env;
  unsigned baud = 230400;
  unsigned app_id = 0;
  long frames = 500;
  int moves = 150;
  bool encrypt = false;
  std::vector<int> restore;
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
    else if (k == "--sdk-version") ;   // the SDK takes its version from the aircraft's answer
    else if (k == "--items") o.items = static_cast<size_t>(atol(v));
    else if (k == "--app-id") o.app_id = static_cast<unsigned>(atol(v));
    else if (k == "--key-env") o.key_env = v;
    else if (k == "--frames") o.frames = atol(v);
    else if (k == "--moves") o.moves = atoi(v);
    else if (k == "--restore") o.restore = parse_codes(v);
    else if (k == "--encrypt") o.encrypt = atoi(v) != 0;
    else return false;
  }
  return !o.port.empty() && o.items >= 1 && o.items <= 16 && !o.key_env.empty();
}

std::string hex_code(unsigned long code) {
  char buf[16];
  snprintf(buf, sizeof buf, "0x%04lX", code);
  return buf;
}

// One step: our verdict, the SDK's own verdict and the ACK code it stored.
void step(const char *name, bool ok, const std::string &detail, bool sdk_ok, unsigned long sdk_code,
          const std::string &extra = "") {
  emit(std::string("{\"ev\":\"step\",\"step\":\"") + name + "\",\"ok\":" + (ok ? "true" : "false") +
       ",\"sdk_ok\":" + (sdk_ok ? "true" : "false") + ",\"sdk_code\":" + std::to_string(sdk_code) +
       ",\"detail\":" + json_string(detail) + extra + "}");
}

void plain_step(const char *name, bool ok, const std::string &detail, const std::string &extra = "") {
  emit(std::string("{\"ev\":\"step\",\"step\":\"") + name + "\",\"ok\":" + (ok ? "true" : "false") +
       ",\"detail\":" + json_string(detail) + extra + "}");
}

const int TIMEOUT_S = 1;   // the blocking calls' timeout, in seconds

bool set_frequencies(Vehicle *v, const std::vector<int> &codes, const char *name) {
  uint8_t freq[16];
  for (int i = 0; i < 16; i++) freq[i] = 5;   // hold: items beyond the profile's
  for (size_t i = 0; i < codes.size() && i < 16; i++) freq[i] = static_cast<uint8_t>(codes[i]);
  ACK::ErrorCode ack = v->broadcast->setBroadcastFreq(freq, TIMEOUT_S);
  bool sdk_ok = !ACK::getError(ack);
  step(name, sdk_ok, "SDK: " + std::string(sdk_ok ? "success" : "error") + ", ACK code " + hex_code(ack.data),
       sdk_ok, ack.data);
  return sdk_ok;
}

bool set_control(Vehicle *v, bool obtain) {
  ACK::ErrorCode ack = obtain ? v->obtainCtrlAuthority(TIMEOUT_S) : v->releaseCtrlAuthority(TIMEOUT_S);
  bool sdk_ok = !ACK::getError(ack);
  const unsigned long want = obtain ? 2 : 1;   // obtain / release success
  bool ok = sdk_ok && ack.data == want;
  step(obtain ? "obtain_control" : "release_control", ok,
       "SDK: " + std::string(sdk_ok ? "success" : "error") + ", ACK code " + hex_code(ack.data), sdk_ok, ack.data);
  return ok;
}

}  // namespace

int main(int argc, char **argv) {
  Options o;
  if (!parse(argc, argv, o)) {
    fprintf(stderr, "usage: %s --port PATH --items N --key-env VAR [--baud B] [--app-id N] [--frames N] "
                    "[--moves N] [--restore C,C,...] [--encrypt 0|1]\n", argv[0]);
    return 2;
  }
  const char *key = getenv(o.key_env.c_str());
  if (!key) {
    fprintf(stderr, "environment variable %s is not set\n", o.key_env.c_str());
    return 2;
  }
  std::string key_text = key;
  capture_sdk_stdout();
  signal(SIGINT, on_signal);
  signal(SIGTERM, on_signal);
  {
    std::string names;
    for (const char *n : FIELD_NAMES) names += (names.empty() ? "" : ",") + json_string(n);
    emit("{\"ev\":\"fields\",\"names\":[" + names + "]}");
  }
#ifdef OSDKC_SET_ENCRYPTION
  const bool can_encrypt = true;
#else
  const bool can_encrypt = false;
#endif

  // The broadcast starts when the port is open: the harness is told before
  // the constructor, which (3.3.x) already queries the version.
  emit("{\"ev\":\"open\",\"port\":" + json_string(o.port) + ",\"baud\":" + std::to_string(o.baud) +
       ",\"can_encrypt\":" + (can_encrypt ? "true" : "false") + "}");
  Vehicle *vehicle = new Vehicle(o.port.c_str(), o.baud, true);
  if (!vehicle->protocolLayer->getDriver()->getDeviceStatus()) {
    plain_step("open", false, "the SDK's serial driver could not open " + o.port + " at " + std::to_string(o.baud));
    emit("{\"ev\":\"done\",\"ok\":false}");
    _exit(1);
  }

  bool all_ok = true, in_control = false, frequencies_set = false, refused = false;

  // version, as the user asks for it
  {
    ACK::DroneVersion dv = vehicle->getDroneVersion(TIMEOUT_S);
    bool sdk_ok = !ACK::getError(dv.ack);
    char fw[32];
    uint32_t fwv = vehicle->getFwVersion();
    snprintf(fw, sizeof fw, "%u.%u.%u.%u", fwv >> 24, fwv >> 16 & 0xFF, fwv >> 8 & 0xFF, fwv & 0xFF);
    std::string name(dv.data.version_name, strnlen(dv.data.version_name, sizeof dv.data.version_name));
    std::string id(dv.data.hw_serial_num, strnlen(dv.data.hw_serial_num, sizeof dv.data.hw_serial_num));
    std::string hw(dv.data.hwVersion, strnlen(dv.data.hwVersion, sizeof dv.data.hwVersion));
    bool ok = fwv != 0;
    step("version", ok, std::string("SDK: ") + (sdk_ok ? "success" : "error") + ", ACK code " +
         hex_code(dv.ack.data) + "; hardware " + hw + ", firmware " + fw,
         sdk_ok, dv.ack.data,
         ",\"version_name\":" + json_string(name) + ",\"version_id\":" + json_string(id) +
         ",\"hardware\":" + json_string(hw) + ",\"firmware\":" + std::to_string(fwv));
    all_ok &= ok;
  }

  // activation (3.4 and later run functionalSetUp in it: a second version query)
  if (!g_stop) {
    Vehicle::ActivateData data;
    memset(&data, 0, sizeof data);
    data.ID = o.app_id;
    data.encKey = &key_text[0];
    data.version = vehicle->getFwVersion();
    g_session.record = true;
    ACK::ErrorCode ack = vehicle->activate(&data, TIMEOUT_S);
    bool sdk_ok = !ACK::getError(ack);
    refused = vehicle->broadcast == 0 || vehicle->control == 0;
    bool ok = sdk_ok && ack.data == 0 && !refused;
    std::string detail = "SDK: " + std::string(sdk_ok ? "success" : "error") + ", ACK code " + hex_code(ack.data);
    if (refused) {
      char fw[16];
      snprintf(fw, sizeof fw, "0x%08X", static_cast<unsigned>(vehicle->getFwVersion()));
      detail += std::string("; the SDK set up no broadcast and no control for hardware ") +
                vehicle->getHwVersion() + ", firmware " + fw;
    }
    step("activation", ok, detail, sdk_ok, ack.data, std::string(",\"refused\":") + (refused ? "true" : "false"));
    all_ok &= ok;
    if (ok && o.encrypt && can_encrypt) {
#ifdef OSDKC_SET_ENCRYPTION
      vehicle->setEncryption(true);
#endif
    }
  }
  if (refused) {
    emit("{\"ev\":\"done\",\"ok\":false,\"refused\":true}");
    _exit(1);
  }
  vehicle->broadcast->setUserBroadcastCallback(on_broadcast, 0);

  // every item at 50 Hz, then the broadcast as the SDK decodes it
  if (!g_stop) {
    all_ok &= set_frequencies(vehicle, std::vector<int>(o.items, DataBroadcast::FREQ_50HZ), "frequencies");
    frequencies_set = true;
  }
  if (!g_stop) {
    long start;
    {
      std::lock_guard<std::mutex> lock(g_session.m);
      start = g_session.broadcasts;
    }
    auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(o.frames * 20 * 3 + 2000);
    long got = 0;
    while (!g_stop && std::chrono::steady_clock::now() < deadline) {
      {
        std::lock_guard<std::mutex> lock(g_session.m);
        got = g_session.broadcasts - start;
      }
      if (got >= o.frames) break;
      usleep(20000);
    }
    bool ok = got >= o.frames;
    plain_step("broadcast", ok, std::to_string(got) + " broadcasts decoded by the SDK after the frequency change",
               ",\"frames\":" + std::to_string(got));
    all_ok &= ok;
  }

  if (!g_stop) {
    in_control = set_control(vehicle, true);
    all_ok &= in_control;
  }
  if (!g_stop && in_control) {
    const uint8_t flag = Control::HORIZONTAL_VELOCITY | Control::VERTICAL_VELOCITY | Control::YAW_RATE |
                         Control::HORIZONTAL_GROUND | Control::STABLE_ENABLE;
    const float vx = 2.0f, vy = 1.0f, vz = 0.5f, yaw_rate = 10.0f;
    int sent = 0;
    for (; sent < o.moves && !g_stop; sent++) {
      vehicle->control->flightCtrl(Control::CtrlData(flag, vx, vy, vz, yaw_rate));
      usleep(20000);
    }
    Telemetry::Vector3f v;
    Telemetry::SDKInfo info;
    {
      std::lock_guard<std::mutex> lock(g_session.m);
      v = g_session.velocity;
      info = g_session.info;
    }
    bool follows = std::abs(v.x - vx) < 0.1f * vx && std::abs(v.y - vy) < 0.1f * vy &&
                   std::abs(v.z - vz) < 0.1f * vz && info.deviceStatus == 2;
    char text[220];
    snprintf(text, sizeof text, "%d commands (flag 0x%02X, %.1f %.1f %.1f m/s, %.0f deg/s); SDK reads velocity "
             "%.3f %.3f %.3f, device %u, mode %u", sent, flag, vx, vy, vz, yaw_rate, v.x, v.y, v.z,
             static_cast<unsigned>(info.deviceStatus), static_cast<unsigned>(info.controlMode));
    bool ok = follows && sent == o.moves;
    plain_step("movement", ok, text, ",\"sent\":" + std::to_string(sent) + ",\"flag\":" + std::to_string(flag) +
               ",\"mode\":" + std::to_string(info.controlMode));
    all_ok &= ok;
  }

  // Whatever happened above, hand control back and restore the frequencies.
  if (in_control) all_ok &= set_control(vehicle, false);
  if (frequencies_set && !o.restore.empty()) all_ok &= set_frequencies(vehicle, o.restore, "frequency_restore");
  g_session.record = false;
  all_ok &= !g_stop;
  emit(std::string("{\"ev\":\"done\",\"ok\":") + (all_ok ? "true" : "false") +
       ",\"interrupted\":" + (g_stop ? "true" : "false") + "}");
  fflush(g_json);
  _exit(all_ok ? 0 : 1);   // the SDK's threads are not stopped: the process ends here
}
