// The exceptions obbsat throws at its checked entry points.
#pragma once

#include <stdexcept>
#include <string>

namespace obbsat {

/// Input that breaks a documented precondition (a non-finite coordinate, an
/// index out of range, batches of unequal length); the message names which.
class invalid_input : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

/// A backend was requested that is not compiled in or that this CPU cannot run.
class unsupported_backend : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace obbsat
