#pragma once
/// \file patch_names.h
/// One rule for the names of boundary patches and regions, so that every format we write holds a
/// name unchanged and a solver deck, a dolfinx script and a Gmsh view all use the same word:
/// ASCII letters, digits and '_', starting with a letter, at most kMaxNameLength characters (the
/// CalculiX limit), and distinct without regard to case (both upper-case names). Names are made to
/// follow it where they enter (a reader, a rename), and each change is reported.
///
/// The limit is 79, not Abaqus' 80: CalculiX 2.20 stores a set's name with one character of its
/// own appended, in 81 bytes; an 80-character set name prints as an empty one in the .dat, and a
/// static job whose node set, element set and surface have 80-character names dies with a
/// segmentation fault (tests/fem_export_test.cpp, CalculixSolvesOnNamedPatches, runs 79).

#include "meshprep/core/mesh.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace meshprep {

inline constexpr std::size_t kMaxNameLength = 79;
/// The rule, for messages.
inline constexpr const char* kNameRule =
    "a patch name is ASCII letters, digits and '_', starts with a letter and has at most 79 characters";

/// Whether `name` follows the rule (distinctness aside).
bool is_valid_name(std::string_view name);

/// `name` made to follow the rule, distinctness aside: each run of other characters (spaces,
/// punctuation, the bytes of a non-ASCII character) becomes one '_'; a name that does not start
/// with a letter gets "p_" in front; the result is cut to kMaxNameLength. "Träger links" ->
/// "Tr_ger_links", "1st face" -> "p_1st_face", "" -> "p_".
std::string sanitized_name(std::string_view name);

/// A name that had to change.
struct RenamedTag {
  int tag = 0;
  std::string from, to;
};

/// Makes every name of `names` follow the rule and distinct without regard to case (a second
/// "TOP" after "top" becomes "TOP_2"); returns the names that changed, in tag order.
std::vector<RenamedTag> sanitize_names(TagNames& names);

/// The name of `tag`: its entry in `names`, else `prefix` + "_" + tag ("boundary_3").
std::string tag_name(const TagNames& names, int tag, std::string_view prefix);

}  // namespace meshprep
