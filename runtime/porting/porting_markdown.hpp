#pragma once

#include "corpus_run.hpp"

#include <filesystem>
#include <string>

namespace iblkit::porting {

// docs/porting.md: a table per feature group (Shader Model 5.x, 6.x, HLSL 2021, Vulkan
// attributes) with each feature's status, each form, its run, and the kit's edits, refusals and
// warnings in the words the tools print. Paths in messages are relative to the corpus folder,
// so the page does not depend on where it was made. `command` is the command that made it, with
// the options that shape the page (the corpus and the device), as the page names it.
std::string portingMarkdown(const CorpusResults& results, const std::filesystem::path& corpusFolder,
                            const std::string& command);

} // namespace iblkit::porting
