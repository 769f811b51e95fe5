// Internal general entities of the DTD (XML 1.0 section 4.2 "Entity Declarations", 4.4 "XML Processor
// Treatment of Entities").
//
// Illustrator writes <!ENTITY st0 "fill:#F00;"> in the internal subset of the DOCTYPE and uses &st0; in
// attribute values; other tools put whole elements in an entity. pugixml reads the DOCTYPE but leaves
// such references as text, so they are expanded here, on the document text, before pugixml parses it:
//   - the internal subset's <!ENTITY name "value"> declarations are read (the first declaration of a
//     name wins, 4.2); character references in a value are replaced at declaration (4.4.5), entity
//     references in it when the entity is used (4.4.8, "bypassed");
//   - every &name; of a declared internal entity after the DOCTYPE is replaced by its replacement text,
//     recursively, in content (where the text may hold markup, 4.4.2 "included") and in attribute values
//     (where it is escaped so that it cannot end the value);
//   - comments, CDATA sections and processing instructions are copied as they are;
//   - external entities (SYSTEM / PUBLIC) are never read: a reference to one is dropped with a warning;
//     parameter entities are ignored with a warning; predefined entities (&lt; ...), character
//     references and references to undeclared names are left to the XML parser.
// Bounds: kMaxEntityDepth nested expansions and kMaxEntityExpansion bytes of replacement text (and
// kMaxEntityReferences references expanded) in all. A document past them -- the "billion laughs" -- is
// refused with kLimitExceeded; a recursive entity (4.1, "No Recursion") with kCorruptInput.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "curvescan/status.h"

namespace curvescan::svg::detail {

inline constexpr int kMaxEntityDepth = 16;
inline constexpr std::size_t kMaxEntityExpansion = std::size_t{8} << 20;  // bytes of replacement text
inline constexpr std::size_t kMaxEntityReferences = 1'000'000;

/// `xml` with its internal entities expanded, or nullopt when it declares none (the text is used as it
/// is). Warnings (external and parameter entities) go to `warnings`.
[[nodiscard]] Result<std::optional<std::string>> expand_internal_entities(std::string_view xml,
                                                                          std::vector<std::string>& warnings);

}  // namespace curvescan::svg::detail
