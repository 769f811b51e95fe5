// Matching selectors against the XML tree (Selectors Level 3 sections 6-8).
//
// Elements are pugixml nodes; a type selector compares the element's local name (xml_names.h), case-
// sensitively as XML requires, in any namespace (CSS Namespaces 3, section 2: without a default
// namespace declared, an unprefixed type selector matches elements of every namespace). Attribute names
// and values compare case-sensitively too, except values under the "i" flag.
//
// A complex selector is matched right to left. Descendant and sibling combinators backtrack; the
// backtracking is cut with the four-outcome scheme described by Servo's selector matcher (a failure
// that no other ancestor or sibling can fix ends the search at once), which keeps matching linear in
// the number of ancestors and siblings visited for each compound.
//
// Two things would make matching cost n^2 on a flat list of n siblings (20 000 siblings: minutes): the
// structural pseudo-classes (:nth-child, :last-child...) counting siblings for every element, and the
// subsequent-sibling combinator (`a ~ b`) walking back over every earlier sibling when none matches. A
// MatchCache keeps, per parent, the positions of its children (numbered once), and per parent, selector
// and compound, where the earlier siblings decide a `~` walk (one pass over the parent's children), so
// both cost O(1) or O(log n) per element after that.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <mutex>
#include <pugixml.hpp>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "selector.h"

namespace curvescan::svg::css {

/// What matching remembers about one XML tree (the keys are its nodes). Safe to share between threads (a
/// render may be run from several threads on one document).
class MatchCache {
 public:
  /// The 1-based position of an element among its parent's element children, from the start and the end,
  /// and among those of its type (its local name, as type selectors compare: Selectors 4, 14.4.5).
  struct Position {
    std::int64_t from_start = 1;
    std::int64_t from_end = 1;
    std::int64_t of_type_from_start = 1;
    std::int64_t of_type_from_end = 1;
  };
  /// The earlier siblings (by position) at which matching the rest of a selector decides something other
  /// than "try an earlier sibling", with that outcome (matching.cpp's Outcome).
  using DecisiveSiblings = std::vector<std::pair<std::int64_t, std::uint8_t>>;

  MatchCache() = default;
  /// A copy starts empty (what is cached belongs to the tree the copy will be used with).
  MatchCache(const MatchCache&) noexcept {}
  MatchCache& operator=(const MatchCache&) noexcept { return *this; }

  [[nodiscard]] Position position(const pugi::xml_node& element) const;

  /// The decisive siblings under `parent` for compounds[index..] of `selector`, computed by `compute` (one
  /// pass over the parent's children) the first time; null when the cache is full (the caller walks).
  template <typename Compute>
  const DecisiveSiblings* decisive_siblings(const ComplexSelector& selector, std::size_t index,
                                            const pugi::xml_node& parent, Compute&& compute) const {
    const std::lock_guard lock(mutex_);
    const Key key{&selector, index, parent.internal_object()};
    if (const auto found = decisive_.find(key); found != decisive_.end()) return &found->second;
    if (decisive_entries_ >= kMaxDecisiveEntries) return nullptr;
    DecisiveSiblings siblings = compute();  // may call back (other keys): the mutex is recursive
    decisive_entries_ += siblings.size() + 1;
    return &decisive_.emplace(key, std::move(siblings)).first->second;
  }

 private:
  using Key = std::tuple<const ComplexSelector*, std::size_t, const void*>;
  /// 16 bytes each: the cache holds at most 64 MiB of them; past that, `~` walks (slower, same result).
  static constexpr std::size_t kMaxDecisiveEntries = std::size_t{1} << 22;

  mutable std::recursive_mutex mutex_;
  mutable std::unordered_map<const void*, Position> positions_;  // by pugi::xml_node::internal_object()
  mutable std::map<Key, DecisiveSiblings> decisive_;
  mutable std::size_t decisive_entries_ = 0;
};

/// Whether `element` matches every simple selector of `compound`.
[[nodiscard]] bool matches_compound(const CompoundSelector& compound, const pugi::xml_node& element,
                                    const MatchCache& cache);

/// Whether `element` is the subject of `selector`.
[[nodiscard]] bool matches(const ComplexSelector& selector, const pugi::xml_node& element,
                           const MatchCache& cache);

}  // namespace curvescan::svg::css
