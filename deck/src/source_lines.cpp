// SPDX-License-Identifier: GPL-3.0-or-later
// Source loading with #include (see source_lines.hpp).
#include "source_lines.hpp"

#include "text_fields.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <system_error>

namespace hbm::deck::detail {

namespace {

constexpr int kMaxIncludeDepth = 32;

std::filesystem::path identity(const std::filesystem::path& p) {
  std::error_code ec;
  auto c = std::filesystem::weakly_canonical(p, ec);
  return ec ? p.lexically_normal() : c;
}

struct Loader {
  Deck& deck;
  Sources& out;
  std::vector<Diagnostic>& diags;
  std::vector<std::filesystem::path> stack;  // identities of the files being read

  void error(SourceLoc loc, int col, std::string msg) {
    diags.push_back(Diagnostic{Severity::Error, loc, col, std::move(msg)});
  }

  void scan(std::string_view text, std::uint32_t file, int depth) {
    std::size_t pos = 0;
    std::uint32_t line_no = 0;
    while (pos < text.size()) {
      const char* start = text.data() + pos;
      const void* nl = std::memchr(start, '\n', text.size() - pos);
      std::size_t len = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - start)
                           : text.size() - pos;
      pos += len + (nl ? 1 : 0);
      ++line_no;
      std::string_view line(start, len);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      if (!line.empty() && line[0] == '#') {
        if (line.substr(0, 8) == "#include" && (line.size() == 8 || line[8] == ' ' || line[8] == '\t'))
          include(line.substr(8), SourceLoc{file, line_no}, depth);
        continue;  // comment
      }
      out.lines.push_back(SourceLine{line, SourceLoc{file, line_no}});
    }
  }

  void include(std::string_view arg, SourceLoc at, int depth) {
    std::string_view name = text::trim(arg);
    if (name.size() >= 2 && (name.front() == '"' || name.front() == '\'') && name.back() == name.front())
      name = name.substr(1, name.size() - 2);
    if (name.empty()) {
      error(at, 1, "#include without a file name");
      return;
    }
    if (depth + 1 > kMaxIncludeDepth) {
      error(at, 10, "#include nested deeper than 32 levels");
      return;
    }
    const std::filesystem::path base = deck.files[at.file].parent_path();
    const std::filesystem::path target = base / std::filesystem::path(std::string(name));
    const std::filesystem::path id = identity(target);
    for (const auto& s : stack) {
      if (s == id) {
        error(at, 10, "#include cycle: " + target.string() + " is already being read");
        return;
      }
    }
    auto buf = std::make_unique<std::string>();
    if (!read_file(target, *buf)) {
      error(at, 10, "cannot read included file " + target.string());
      return;
    }
    const auto file = static_cast<std::uint32_t>(deck.files.size());
    deck.files.push_back(target);
    deck.included_from.push_back(at);
    std::string_view text = *buf;
    out.buffers.push_back(std::move(buf));
    stack.push_back(id);
    scan(text, file, depth + 1);
    stack.pop_back();
  }
};

}  // namespace

bool read_file(const std::filesystem::path& p, std::string& out) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(p, ec)) return false;
  std::ifstream in(p, std::ios::binary);
  if (!in) return false;
  in.seekg(0, std::ios::end);
  const auto size = in.tellg();
  if (size < 0) return false;
  out.resize(static_cast<std::size_t>(size));
  in.seekg(0, std::ios::beg);
  in.read(out.data(), size);
  return static_cast<bool>(in) || in.eof();
}

void load_sources(std::string_view text, Deck& deck, Sources& out, std::vector<Diagnostic>& diags) {
  out.lines.reserve(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1);
  Loader l{deck, out, diags, {}};
  l.stack.push_back(identity(deck.files[0]));
  l.scan(text, 0, 0);
}

}  // namespace hbm::deck::detail
