#pragma once
// TOML case files: loading, `--set key=value` overrides (like `liggghts -var`), and checking every
// key against the schema so that a misspelt key stops the run with the closest valid name.
#include <toml++/toml.h>

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace isphdem {

// Bad input in a case file or an override; the message names the key and the fix.
class CaseError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class CaseFile {
 public:
  // Parses `path`, applies overrides ("dotted.key=value"; the value is TOML, or a bare string),
  // then checks every key against `known_keys` (dotted paths; elements of arrays of tables are
  // written without an index, e.g. "fluid.blocks.min") and refuses any number that is nan or
  // +-inf (TOML admits them), naming its key and line, or --set.
  static CaseFile load(const std::filesystem::path& path, const std::vector<std::string>& overrides,
                       const std::vector<std::string>& known_keys);

  const toml::table& table() const { return table_; }
  // A copy with one more override ("key=value" as for --set), e.g. the model "auto" chose.
  CaseFile with_override(const std::string& assignment) const;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path directory() const { return path_.parent_path(); }
  bool has(const std::string& key) const;

  // Typed access; the key is a dotted path. Errors name the key and the expected type.
  double number(const std::string& key) const;
  double number(const std::string& key, double fallback) const;
  // A positive number (> 0).
  double positive(const std::string& key) const;
  double positive(const std::string& key, double fallback) const;
  long integer(const std::string& key, long fallback) const;
  bool boolean(const std::string& key, bool fallback) const;
  std::string string(const std::string& key, const std::string& fallback) const;
  std::vector<double> numbers(const std::string& key, std::size_t size) const;
  std::vector<double> numbers(const std::string& key, std::size_t size,
                              const std::vector<double>& fallback) const;
  std::vector<bool> booleans(const std::string& key, std::size_t size,
                             const std::vector<bool>& fallback) const;
  // Elements of an array of tables (e.g. [[fluid.blocks]]), each as a table.
  std::vector<const toml::table*> tables(const std::string& key) const;

  // Where a key was set, for messages: "case.toml line 12" or "--set".
  std::string where(const std::string& key) const;

 private:
  toml::node_view<const toml::node> node(const std::string& key) const;
  [[noreturn]] void type_error(const std::string& key, const std::string& expected) const;

  toml::table table_;
  std::filesystem::path path_;
};

// Reads one typed value from a table element of an array of tables (e.g. one [[walls.boxes]]);
// `context` names it in messages ("walls.boxes[2]").
std::vector<double> table_numbers(const toml::table& t, const std::string& key, std::size_t size,
                                  const std::string& context);

// Edit distance used to suggest the closest known key.
std::size_t edit_distance(const std::string& a, const std::string& b);
std::string closest(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace isphdem
