#pragma once
// Result<T> / Error — the bad-data tier of DESIGN.md §11.
//
// An Error carries one human-readable message that names the file, the field and what was
// expected, e.g.
//   levels/foo.json: colliders[3].size.x: expected a number >= 0, got -2
// Functions that read user data return [[nodiscard]] Result<T>; callers either propagate the
// error or show it and keep their previous state.

#include <string>
#include <string_view>
#include <utility>
#include <variant>

#include "ossa/assert.h"

namespace ossa {

struct Error {
  std::string message;

  // Builds "file: field: what". Empty parts are left out.
  static Error at(std::string_view file, std::string_view field, std::string_view what);
};

namespace detail {
// Result::value() on an error: prints "Result::value() on an error: <the error's message>"
// to stderr (so an embedder sees which file, field and expectation failed) and aborts.
[[noreturn]] void value_on_error(const Error& error);
}  // namespace detail

template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : v_(std::move(value)) {}           // NOLINT: implicit by design
  Result(Error error) : v_(std::move(error)) {}       // NOLINT: implicit by design

  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }

  // The value; on an error, prints the error's message and aborts (detail::value_on_error).
  // Check ok() first where bad data is possible.
  T& value() & { check_value(); return std::get<0>(v_); }
  const T& value() const& { check_value(); return std::get<0>(v_); }
  T&& value() && { check_value(); return std::get<0>(std::move(v_)); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }

  const Error& error() const { OSSA_ASSERT(!ok(), "Result::error() on a value"); return std::get<1>(v_); }
  const std::string& message() const { return error().message; }

 private:
  void check_value() const {
    if (!ok()) detail::value_on_error(std::get<1>(v_));
  }

  std::variant<T, Error> v_;
};

// Result of an operation with no value.
template <>
class [[nodiscard]] Result<void> {
 public:
  Result() = default;
  Result(Error error) : error_(std::move(error)), ok_(false) {}  // NOLINT: implicit by design

  bool ok() const { return ok_; }
  explicit operator bool() const { return ok_; }
  const Error& error() const { OSSA_ASSERT(!ok_, "Result::error() on success"); return error_; }
  const std::string& message() const { return error().message; }

 private:
  Error error_;
  bool ok_ = true;
};

using Status = Result<void>;

}  // namespace ossa
