#pragma once
// A bound on a program's teardown, once its work is done.
//
// After a run, a process still deletes its DDS entities and joins the vendor's threads. Fast
// DDS 2.x can deadlock there (a timer's unregistration waiting on a thread that waits on a
// send lock: eProsima/Fast-DDS#4026, #6193), and a process that never exits keeps the host's
// `plexus launch` waiting for it, and a test waiting for that. So every plexus program says,
// when its work is done, which exit code it ends with: if it is still alive `seconds` later,
// it prints one line naming itself and the cause, flushes its logs and leaves with that code
// (_exit: no more destructors, the ones that hung included).

#include <string>

namespace plexus {

/// The teardown bound of plexus programs, in seconds: far above a normal teardown (tens of ms,
/// up to about a second when DDS Security is on), far below a test's or an operator's patience.
inline constexpr double kTeardownDeadlineS = 10.0;

/// Arms the bound and returns `rc`, so that `return exit_within(rc, kTeardownDeadlineS, "name");`
/// arms it before the function's locals (the participant) are destroyed. Arming it again moves
/// the deadline and the code.
int exit_within(int rc, double seconds, const std::string& who);

}  // namespace plexus
