#pragma once

#include "corpus_run.hpp"

#include <filesystem>
#include <string>

namespace iblkit::porting {

// docs/porting.md: a table per feature group (Shader Model 5.x, 6.x, HLSL 2021, Vulkan
// attributes) with each feature's status, each form, its run, and the kit's edits, refusals and
// warnings in the words the tools print. Paths in messages are relative to the corpus folder,
// so the page does not depend on where it was made.
std::string portingMarkdown(const CorpusResults& results, const std::filesystem::path& corpusFolder);

} // namespace iblkit::porting
