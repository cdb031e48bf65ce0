#pragma once
// Reading what the tests check in docs/: a page's text, and the code spans (`...`) it quotes.
#include <cctype>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

namespace covsim::test {

inline std::string doc_text(const std::string& page) {
  std::ifstream in(std::string(COVSIM_SOURCE_DIR) + "/docs/" + page);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The first code span of `text` that starts with `prefix`, whole (prefix included).
inline std::optional<std::string> code_span_starting(const std::string& text,
                                                     const std::string& prefix) {
  const auto at = text.find("`" + prefix);
  if (at == std::string::npos) return std::nullopt;
  const auto end = text.find('`', at + 1);
  if (end == std::string::npos) return std::nullopt;
  return text.substr(at + 1, end - at - 1);
}

// The code span that follows `words` in `text`, after white space only.
inline std::optional<std::string> code_span_after(const std::string& text,
                                                  const std::string& words) {
  auto at = text.find(words);
  if (at == std::string::npos) return std::nullopt;
  at += words.size();
  while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at])))
    ++at;
  if (at >= text.size() || text[at] != '`') return std::nullopt;
  const auto end = text.find('`', at + 1);
  if (end == std::string::npos) return std::nullopt;
  return text.substr(at + 1, end - at - 1);
}

}  // namespace covsim::test
