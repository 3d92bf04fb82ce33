// A tty in raw mode for the serial bridge: 8 data bits, no parity, one stop bit, no flow
// control, no echo, no line discipline (termios cfmakeraw), CLOCAL | CREAD, non-blocking.
#pragma once

#include <string>

namespace plexus::link {

/// Baud rates the serial bridge accepts: 115200 up to 1000000, the ones termios names
/// (115200, 230400, 460800, 500000, 576000, 921600, 1000000).
bool supported_baud(long baud);

/// Opens `path` (O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC) and sets raw mode at `baud`.
/// Returns the fd, or -1 with `error` set to one line naming the path and the cause.
int open_serial(const std::string& path, long baud, std::string& error);

}  // namespace plexus::link
