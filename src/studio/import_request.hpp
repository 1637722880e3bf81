// feel::studio — the Studio's import (docs/import.md, docs/studio.md "Import"): a file the
// browser sends in an `import_file` message becomes a new sensation file in the workspace.
#pragma once

#include <cstddef>

#include <nlohmann/json.hpp>

namespace feel::studio {

class Workspace;

// The largest file the Studio imports (1 MiB, the workspace's file limit); its base64 text
// is kMaxImportBase64Chars, what the protocol schema allows for import_file.data.
inline constexpr size_t kMaxStudioImportBytes = 1u << 20;
inline constexpr size_t kMaxImportBase64Chars = (kMaxStudioImportBytes + 2) / 3 * 4;
// The most notes an `imported` answer carries (the schema's maxItems); more are counted.
inline constexpr size_t kMaxImportNotes = 64;

// Decodes `m` (an import_file message the protocol schema accepted), converts it with the
// importers of src/import/, saves it as a new NAME.feel.json in the workspace (NAME from
// the file's name; NAME_2 ... if taken) and returns the `imported` answer. Throws
// std::exception with a sentence for any refusal (bad base64, a file the importer refuses,
// a file the workspace refuses).
[[nodiscard]] nlohmann::json import_into_workspace(Workspace& workspace, const nlohmann::json& m);

}  // namespace feel::studio
