// The one exception type for failures the user can act on: its message is the single line the user
// sees, its kind the exit code of the urbis command.
#pragma once

#include <stdexcept>
#include <string>

namespace urbis {

/// What went wrong, one value per exit code of the urbis command (the table in docs/cli.md).
enum class FailureKind : int {
    BadInput = 1,     ///< an input file or its data: missing, unreadable, malformed, nothing usable
    Usage = 2,        ///< a bad, missing or unknown option or option value
    OutOfMemory = 3,  ///< host or device memory, including the up-front refusals
    Device = 4,       ///< the GPU: none usable when asked for, or a CUDA call failed
    Output = 5,       ///< an output file cannot be written
};

/// A failure with a one-line message that names the problem and the file or option.
class InputError : public std::runtime_error {
public:
    /// `message` is the line the user sees; `kind` picks the exit code.
    explicit InputError(const std::string& message, FailureKind kind = FailureKind::BadInput)
        : std::runtime_error(message), kind_(kind) {}

    /// The kind of failure, hence the exit code.
    FailureKind kind() const noexcept { return kind_; }

private:
    FailureKind kind_;
};

} // namespace urbis
