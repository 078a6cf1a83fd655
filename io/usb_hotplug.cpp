#include "io/usb_hotplug.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#ifdef LATTICE_HAVE_LIBUSB
#include <libusb.h>
#endif

namespace lattice::io {
namespace {

using Clock = std::chrono::steady_clock;

#ifdef LATTICE_HAVE_LIBUSB
// Owns a libusb context with an arrival callback; empty when libusb cannot
// start here (no USB in a container) or has no hot-plug support.
class HotplugListener {
 public:
  HotplugListener() {
    if (libusb_init(&context_) != 0) {
      context_ = nullptr;
      reason_ = "libusb could not start (no USB access here)";
      return;
    }
    if (!libusb_has_capability(LIBUSB_CAP_HAS_HOTPLUG)) {
      reason_ = "libusb has no hot-plug support on this platform";
      return;
    }
    int rc = libusb_hotplug_register_callback(context_, LIBUSB_HOTPLUG_EVENT_DEVICE_ARRIVED, LIBUSB_HOTPLUG_NO_FLAGS,
                                              LIBUSB_HOTPLUG_MATCH_ANY, LIBUSB_HOTPLUG_MATCH_ANY,
                                              LIBUSB_HOTPLUG_MATCH_ANY, &HotplugListener::onArrival, this, &handle_);
    if (rc != LIBUSB_SUCCESS) {
      reason_ = "libusb refused a hot-plug callback";
      return;
    }
    active_ = true;
  }
  ~HotplugListener() {
    if (active_) libusb_hotplug_deregister_callback(context_, handle_);
    if (context_ != nullptr) libusb_exit(context_);
  }
  HotplugListener(const HotplugListener&) = delete;
  HotplugListener& operator=(const HotplugListener&) = delete;

  bool active() const { return active_; }
  const std::string& reason() const { return reason_; }

  // Waits up to `seconds` for events; true if a device arrived.
  bool waitForArrival(double seconds) {
    timeval tv{};
    tv.tv_sec = static_cast<time_t>(seconds);
    tv.tv_usec = static_cast<suseconds_t>((seconds - std::floor(seconds)) * 1e6);
    libusb_handle_events_timeout_completed(context_, &tv, nullptr);
    return arrived_.exchange(false);
  }

 private:
  static int LIBUSB_CALL onArrival(libusb_context*, libusb_device*, libusb_hotplug_event, void* self) {
    static_cast<HotplugListener*>(self)->arrived_ = true;
    return 0;  // stay registered
  }

  libusb_context* context_ = nullptr;
  libusb_hotplug_callback_handle handle_{};
  bool active_ = false;
  std::atomic<bool> arrived_{false};
  std::string reason_;
};
#endif

}  // namespace

std::string usbWaitMechanism(bool useLibusb) {
  if (!useLibusb) return "polling sysfs";
#ifdef LATTICE_HAVE_LIBUSB
  HotplugListener listener;
  return listener.active() ? "libusb hot-plug events" : "polling sysfs (" + listener.reason() + ")";
#else
  return "polling sysfs (built without libusb)";
#endif
}

std::vector<SerialPortInfo> waitForUsbSerialPorts(const UsbWaitOptions& options) {
  const bool forever = options.timeoutSeconds <= 0.0;
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(forever ? 0.0 : options.timeoutSeconds));
  const double poll = std::clamp(options.pollSeconds, 0.01, 5.0);
#ifdef LATTICE_HAVE_LIBUSB
  std::unique_ptr<HotplugListener> listener;
  if (options.useLibusb) {
    listener = std::make_unique<HotplugListener>();
    if (!listener->active()) listener.reset();
  }
  // After an arrival the driver still has to bind and create the tty.
  double quickRescanUntil = -1.0;
  const auto start = Clock::now();
#endif
  for (;;) {
    auto ports = usbSerialPorts(listSerialPorts(options.sysfsRoot, options.devRoot));
    if (!ports.empty()) return ports;
    double left = forever ? poll : std::chrono::duration<double>(deadline - Clock::now()).count();
    if (left <= 0.0) return {};
    double slice = std::min(poll, left);
#ifdef LATTICE_HAVE_LIBUSB
    if (listener) {
      double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
      if (elapsed < quickRescanUntil) {
        std::this_thread::sleep_for(std::chrono::duration<double>(std::min(0.05, slice)));
      } else if (listener->waitForArrival(slice)) {
        quickRescanUntil = std::chrono::duration<double>(Clock::now() - start).count() + 3.0;
      }
      continue;
    }
#endif
    std::this_thread::sleep_for(std::chrono::duration<double>(slice));
  }
}

}  // namespace lattice::io
