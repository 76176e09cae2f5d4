// writeFilesWhole (see file_write.h).
#include "core/file_write.h"

#include "core/strings.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include <unistd.h>

namespace ispm {
namespace {

bool writeBytes(const std::string& path, std::string_view bytes) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    file.close();
    return static_cast<bool>(file);
}

} // namespace

void writeFilesWhole(const std::vector<std::pair<std::string, std::string_view>>& files) {
    std::vector<std::string> temporaries;
    std::error_code error;
    const auto removeTemporaries = [&] {
        for (const std::string& t : temporaries)
            if (!t.empty()) std::filesystem::remove(t, error);
    };
    for (const auto& [path, bytes] : files) {
        const std::string temporary = strCat(path, ".tmp-", getpid());
        if (!std::ofstream(temporary, std::ios::binary).is_open()) {
            temporaries.emplace_back(); // none beside it: written in place below
            continue;
        }
        temporaries.push_back(temporary);
        if (!writeBytes(temporary, bytes)) {
            removeTemporaries();
            throw std::runtime_error(strCat(path, ": cannot write the file"));
        }
    }
    for (size_t i = 0; i < files.size(); ++i) {
        const std::string& path = files[i].first;
        const bool written = temporaries[i].empty()
                                 ? writeBytes(path, files[i].second)
                                 : (std::filesystem::rename(temporaries[i], path, error), !error);
        if (!written) {
            removeTemporaries();
            throw std::runtime_error(strCat(path, ": cannot write the file"));
        }
        temporaries[i].clear();
    }
}

} // namespace ispm
