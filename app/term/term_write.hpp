#pragma once
// Bytes toward a peer that reads them (a program's pseudo-terminal, a serial
// line, the host terminal): every byte, waiting briefly while the peer's
// queue is full, never for long: a peer that stops reading loses keys rather
// than hanging the terminal.
#include <cstdint>
#include <span>

namespace lattice::app {

// Returns the bytes written; gives up after about kPeerWaitMs of no room.
std::size_t writeToPeer(int fd, std::span<const std::uint8_t> bytes);

inline constexpr int kPeerWaitMs = 2000;

}  // namespace lattice::app
