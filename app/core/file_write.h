// Files written whole or not at all: each goes to a temporary file beside its path and is renamed
// into place, so a failed write (a full disk) leaves whatever was there as it was.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ispm {

// Writes every (path, bytes) pair to its temporary file first and renames them only when all
// were written: a set of files (an OBJ and its MTL) lands together or not at all. Where no file
// can be made beside a path (a folder that is not writable, the file itself is) that one is
// written in place. Throws std::runtime_error naming the path that failed.
void writeFilesWhole(const std::vector<std::pair<std::string, std::string_view>>& files);

inline void writeFileWhole(const std::string& path, std::string_view bytes) {
    writeFilesWhole({{path, bytes}});
}

} // namespace ispm
