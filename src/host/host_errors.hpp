// feel::host — turning the device's answers and the host's own checks into Status values.
#pragma once

#include <string>
#include <string_view>

#include "feel/host/result.hpp"
#include "feel/protocol/command_answer.hpp"

namespace feel::host {

// The engine's Error carried by a device's answer (field, value, range, rule).
[[nodiscard]] Error error_from_status(const protocol::CommandAnswer& status);

// ok for a CommandStatus without error; else the Status of its code, its message
// "`what`: <field> = <value> is out of range (allowed ..)" and its Error as detail.
[[nodiscard]] Status status_from_command(const protocol::CommandAnswer& status, std::string_view what);

// The ErrorKind of an engine ErrorCode (ok -> ok).
[[nodiscard]] ErrorKind kind_of(ErrorCode code) noexcept;

// A Status for an engine Error found on the host (validate_effect, the capability checks):
// "`what`: " + error.message(), of the kind of its code.
[[nodiscard]] Status status_from_error(const Error& error, std::string_view what);

// A stable C string with the text of `rule` (Error::rule must outlive the Error). The
// rules a device sends are a small fixed set of sentences; past a bound of distinct texts
// a generic sentence is returned instead of growing without end.
[[nodiscard]] const char* intern_rule(std::string_view rule);

}  // namespace feel::host
