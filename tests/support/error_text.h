// The message of the rays::Error a piece of code throws, for tests that check error texts.
#pragma once
#include <string>

#include "rays/error.h"

namespace rays::test {

/// what() of the rays::Error that f() throws, or "(no error)" when it returns.
template <class F>
std::string errorText(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace rays::test
