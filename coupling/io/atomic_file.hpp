// Replacing a file so that readers (ParaView polling a running simulation, a crash halfway) only
// ever see the old complete file or the new complete one: write a temporary file next to the
// target, then rename it over the target (rename is atomic within one file system).
#pragma once

#include <filesystem>
#include <string_view>

namespace isphdem {

// DIR/.NAME.tmp: hidden, so that globs such as snap_*.h5 never match a half-written file, and in
// the same directory, so that the rename cannot cross file systems.
std::filesystem::path temporary_path_for(const std::filesystem::path& target);

// True for names temporary_path_for produces (to clean up after a crash).
bool is_temporary_name(std::string_view file_name);

// Writes `contents` to temporary_path_for(target) and renames it to `target`. Throws
// std::runtime_error naming the file on failure, leaving `target` as it was.
void write_file_atomically(const std::filesystem::path& target, std::string_view contents);

}  // namespace isphdem
