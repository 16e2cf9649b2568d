// libFuzzer target: the TetGen reader on arbitrary bytes (scripts/fuzz.sh runs it). The input is
// the .node text, then the .ele text and optionally the .face text, separated by NUL bytes.
#include "tet_mesh_fuzzer.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace meshprep;
  const std::string_view input = fuzz::as_text(data, size);
  const std::size_t ele = input.find('\0');
  if (ele == std::string_view::npos) return 0;
  const std::size_t face = input.find('\0', ele + 1);
  detail::TetgenTexts texts;
  texts.mesh_name = texts.node_name = "input.node";
  texts.ele_name = "input.ele";
  texts.face_name = "input.face";
  texts.node = input.substr(0, ele);
  texts.ele = input.substr(ele + 1, face == std::string_view::npos ? std::string_view::npos : face - ele - 1);
  if (face != std::string_view::npos) texts.face = input.substr(face + 1);
  fuzz::refuse_only_with_meshprep_errors([&] {
    TetReadReport report;
    const TetMesh mesh = detail::read_tet_mesh_from_texts(texts, &report);
    fuzz::require_valid_tet_mesh(mesh, report);
  });
  return 0;
}
