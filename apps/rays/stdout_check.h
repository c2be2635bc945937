// What a command prints on stdout must arrive: flushStdout pushes it out and turns a write error
// (a full disk, `> /dev/full`) into an Error, so that the command does not report success.
#pragma once

namespace rays::cli {

/// Flushes std::cout and stdout; throws Error "rays: error: cannot write to standard output: REASON"
/// when anything written to them so far failed.
void flushStdout();

}  // namespace rays::cli
