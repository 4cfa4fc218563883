#include "app/text_output.h"

#include "export/output_file.h"

namespace simeco::app {

void writeText(draw::OutputBatch& batch, const std::filesystem::path& path, const std::string& text) {
    batch.write(path, [&](const std::filesystem::path& temporary) {
        exporter::OutputFile file(temporary);
        file.write(text.data(), text.size());
    });
}

} // namespace simeco::app
