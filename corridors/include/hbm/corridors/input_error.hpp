// SPDX-License-Identifier: GPL-3.0-or-later
// InputError: the one exception type for bad input to hbm-corridors (case file, time-history
// CSV, corridor file). Its message reads like a compiler diagnostic,
// "FILE:LINE: error: what is wrong", so the command line can print it as it is and exit 1.
#pragma once

#include <stdexcept>
#include <string>

namespace hbm::corridors {

class InputError : public std::runtime_error {
public:
  /// line = 0 means "the file as a whole" (no line number is printed).
  InputError(const std::string& file, long line, const std::string& message)
      : std::runtime_error(format(file, line, message)), file_(file), line_(line) {}

  const std::string& file() const { return file_; }
  long line() const { return line_; }

private:
  static std::string format(const std::string& file, long line, const std::string& message) {
    std::string s;
    s.append(file);
    if (line > 0) {
      s.push_back(':');
      s.append(std::to_string(line));
    }
    s.append(": error: ");
    s.append(message);
    return s;
  }
  std::string file_;
  long line_;
};

}  // namespace hbm::corridors
