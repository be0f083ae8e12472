#pragma once

// The reference texts generated from the scene reader's key tables: the key tables of
// docs/scenes.md and the fuzzer's dictionary fuzz/scene.dict. A test holds the committed files to
// them; `tide scene-keys` rewrites both.

#include <string>
#include <string_view>

namespace tide::io {

/// The command, from the repository root, that rewrites both files from the tables.
inline constexpr std::string_view scene_keys_regenerate_command =
    "build/apps/tide scene-keys --docs docs/scenes.md --dict fuzz/scene.dict";

/// `markdown` with the text between each `<!-- scene keys: NAME -->` and the next
/// `<!-- end scene keys -->` replaced by the table of the section NAME. std::invalid_argument
/// when a marker names no section, is not closed, or a section has no marker.
std::string with_generated_key_tables(std::string_view markdown);

/// The libFuzzer dictionary: every key of every section, every name a value may take, and JSON
/// tokens and numbers at the edges of what the reader accepts.
std::string scene_fuzz_dictionary();

}  // namespace tide::io
