#include "io/serial_settings.hpp"

namespace lattice::io {

namespace {

using S = SerialOptions;

// Each help line says why a user would set it. The ranges: 50 baud is the
// slowest rate Linux sets, 4 Mbaud the fastest common UARTs reach.
constexpr lattice::Setting<S> kSerialRows[] = {
    whole<&S::baud>("baud", {50, 4000000}, "the line's speed: match the terminal's setup (9600, 19200, 38400...)"),
    choiceOf<kFlowControlNames, &S::flow>(
        "flow", "xonxoff (DC1/DC3, the Tektronix default), rtscts (hardware) or none: as the terminal is set up"),
    whole<&S::dataBits>("data-bits", {7, 8}, "data bits per character: 7 or 8, as the terminal is set up"),
    choiceOf<kParityNames, &S::parity>("parity", "none, even or odd: as the terminal is set up"),
    whole<&S::stopBits>("stop-bits", {1, 2}, "stop bits: 1 or 2, as the terminal is set up"),
    number<&S::stallTimeoutSeconds>(
        "stall-timeout", {0.001, 1e6},
        "give up (exit 6, resumable) when flow control holds the line this many seconds: a terminal switched off"),
    onOff<&S::pace>("pace", "limit the rate to the baud rate ourselves, for lines that do not (a pty, a network "
                            "bridge)"),
};

constexpr SettingsSchema<S> kSerialSchema{"serial line", kSerialRows, [] { return S{}; }};

}  // namespace

const SettingsSchema<SerialOptions>& serialSettings() { return kSerialSchema; }

}  // namespace lattice::io
