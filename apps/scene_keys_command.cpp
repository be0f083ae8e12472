#include "scene_keys_command.hpp"

#include <fstream>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "run_command.hpp"
#include "tide/io/atomic_file.hpp"
#include "tide/io/scene_key_reference.hpp"

namespace tide::app {

int write_scene_keys(const std::filesystem::path& docs_page, const std::filesystem::path& dictionary) {
  std::ifstream in(docs_page, std::ios::binary);
  if (!in) {
    std::cerr << "tide: scene-keys: cannot read " << docs_page.string() << '\n';
    return exit_bad_input;
  }
  const std::string page{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::string updated;
  try {
    updated = io::with_generated_key_tables(page);
  } catch (const std::invalid_argument& error) {
    std::cerr << "tide: " << docs_page.string() << ": " << error.what() << '\n';
    return exit_bad_input;
  }
  io::replace_text_atomically(docs_page, updated);
  io::replace_text_atomically(dictionary, io::scene_fuzz_dictionary());
  std::cout << "tide: wrote the key tables of " << docs_page.string() << " and " << dictionary.string() << '\n';
  return exit_ok;
}

}  // namespace tide::app
