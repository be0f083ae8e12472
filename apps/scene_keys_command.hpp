#pragma once

#include <filesystem>

namespace tide::app {

/// `tide scene-keys` (hidden; for maintainers): rewrites the key tables of `docs_page`
/// (docs/scenes.md) and the fuzz dictionary `dictionary` (fuzz/scene.dict) from the scene
/// reader's key tables. Exit code 2 when the page's markers do not match the tables.
int write_scene_keys(const std::filesystem::path& docs_page, const std::filesystem::path& dictionary);

}  // namespace tide::app
