#pragma once

// A tag distinct for every requester a process or its restarts make (the process id, the start
// time, a counter), to start request ids with: services answer a repeated request id from
// memory, so a restarted program counting from 1 again must not reuse its previous life's ids.

#include <string>

namespace avc {

std::string SessionTag();

}  // namespace avc
