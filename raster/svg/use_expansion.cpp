// How many elements the drawing walk meets with every <use> expanded (DocumentIndex::expanded_elements),
// counted before anything is drawn. A "billion laughs" of <use> (each level using the one below ten times,
// six levels deep) is a few hundred bytes that expand to 10^6 elements: the walk used to draw all of them
// before DocumentLimits::max_elements stopped it, seconds of work for nothing. Counted here, memoised per
// referenced element, the document is refused at once with the same error.
//
// The count follows the drawing walk (document.cpp), so that it never exceeds what the walk would count:
//  - every element the walk meets counts one, drawn or not (defs, unknown and foreign elements too);
//  - the children of g, a, svg (the root included) and the child a <switch> picks count when their parent
//    is drawn: an SVG graphics element or a curve element whose conditional attributes hold and whose
//    `display` is not none;
//  - a drawn <use> counts its target as drawn there: a <symbol> or <svg> target its children (unless its
//    own `display` is none), any other target itself and its content;
//  - the content of every <mask>, <pattern> and <marker> counts once, as if drawn once. Each is drawn
//    once per reference (a pattern tile once per painted element, a marker once per vertex), which the
//    walk keeps counting as it draws, against the same limit; up front, only the content of one drawing is
//    known without reading the references' paths and paints;
//  - a <use> that leads back to an element whose count is being taken (a <use> of its own ancestor, or of
//    a <use> that comes back to it) counts only itself: the walk skips it as circular (SVG 1.1 5.6). Such
//    a cut can make a memoised count smaller than that element's count elsewhere, never larger.
// Not counted (the walk meets them, or not, depending on more than the tree): children of <text> (its
// content is laid out, not walked), clipPath children (geometry), <feImage> and <textPath> references,
// elements hidden by a clip or mask that covers nothing. So the count is a lower bound of the walk's, and a
// document refused here is one the walk would have refused after the work.
//
// The sums saturate at the largest std::uint64_t: 32 levels of ten uses overflow 64 bits.
#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

#include "cascade.h"
#include "css/syntax.h"
#include "curvescan/svg/number.h"
#include "document_index.h"
#include "xml_names.h"

namespace curvescan::svg::detail {
namespace {

std::uint64_t saturating_add(std::uint64_t a, std::uint64_t b) {
  return a > std::numeric_limits<std::uint64_t>::max() - b ? std::numeric_limits<std::uint64_t>::max()
                                                           : a + b;
}

// Whether a cascaded `display` value is none: trimmed, keyword case ignored (CSS Values 4, 6.1).
bool is_none(std::string_view value) { return css::ascii_equal_ignoring_case(trim_whitespace(value), "none"); }

bool walks_children(std::string_view name) {
  return name == "g" || name == "a" || name == "svg" || name == "switch";
}

bool has_element_child(const pugi::xml_node& node) {
  for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling()) {
    if (child.type() == pugi::node_element) return true;
  }
  return false;
}

// What is counted for an element: the element itself with what the walk draws under it where it stands,
// or its content alone (a <symbol>'s children when a <use> draws it, a <mask>'s when it is applied).
enum class Part : std::uint8_t { kElement, kContent };

}  // namespace

std::uint64_t DocumentIndex::count_expanded_elements(const pugi::xml_node& root,
                                                     const std::vector<pugi::xml_node>& resources,
                                                     const css::StyleSheets* style_sheets) const {
  // display: none hides an element and all it holds (cascaded as the renderer does; a case or spelling the
  // renderer would not take counts as hidden, which only lowers the count). Asked only of elements that
  // have something to hide.
  const auto displayed = [&](const pugi::xml_node& node) {
    const std::optional<std::string> display = cascaded_value(node, "display", style_sheets);
    return !display || !is_none(*display);
  };
  const auto drawn = [](const ElementFacts& facts) {
    return (facts.role == ElementRole::kRendered || facts.role == ElementRole::kCurve) &&
           facts.conditions_hold;
  };
  // The element a <use> draws, or an empty node when its reference is broken.
  const auto use_target = [&](const pugi::xml_node& use) -> pugi::xml_node {
    pugi::xml_attribute href = use.attribute("href");
    if (!href) href = use.attribute("xlink:href");
    const std::string_view reference = href.value();
    if (reference.size() < 2 || reference.front() != '#') return {};
    const auto found = ids_.find(std::string(reference.substr(1)));
    return found == ids_.end() ? pugi::xml_node() : found->second;
  };

  // Memo per (element, part): its state in the depth-first walk and its count when done.
  enum class State : std::uint8_t { kNew, kCounting, kDone };
  const auto slot = [&](const pugi::xml_node& node, Part part) {
    return position(node) * 2 + (part == Part::kContent ? 1 : 0);
  };
  std::vector<State> states(facts_.size() * 2, State::kNew);
  std::vector<std::uint64_t> counts(facts_.size() * 2, 0);

  // An explicit stack (a chain of 10^5 <use>s would overflow the call stack): each frame sums the counts
  // of its dependencies, kept in `pending` from `first` on, taken one at a time.
  struct Dependency {
    pugi::xml_node node;
    Part part;
  };
  struct Frame {
    pugi::xml_node node;
    Part part;
    std::size_t first;  // its dependencies: pending[first, pending.size()) while it is the top frame
    std::uint64_t sum;
  };
  std::vector<Dependency> pending;
  std::vector<Frame> frames;

  const auto open = [&](const pugi::xml_node& node, Part part) {
    states[slot(node, part)] = State::kCounting;
    Frame frame{node, part, pending.size(), part == Part::kElement ? 1u : 0u};
    if (part == Part::kContent) {
      if (local_name(node) == "switch") {  // the child the switch picks (switch.h), as render_switch does
        for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling()) {
          if (child.type() != pugi::node_element) continue;
          const ElementFacts& child_facts = facts(child);
          if (!is_switch_candidate(child_facts.role) || !child_facts.conditions_hold) continue;
          pending.push_back({child, Part::kElement});
          break;
        }
      } else {
        for (pugi::xml_node child = node.last_child(); child; child = child.previous_sibling()) {
          if (child.type() == pugi::node_element) pending.push_back({child, Part::kElement});
        }
      }
    } else {
      const ElementFacts& own = facts(node);
      const std::string_view name = local_name(node);
      const bool is_use = name == "use";
      if (drawn(own) && (is_use || has_element_child(node)) && displayed(node)) {
        if (walks_children(name)) pending.push_back({node, Part::kContent});
        if (is_use) {
          if (const pugi::xml_node target = use_target(node)) {
            const std::string_view target_name = local_name(target);
            if (target_name == "symbol" || target_name == "svg") {
              if (displayed(target)) pending.push_back({target, Part::kContent});
            } else {
              pending.push_back({target, Part::kElement});
            }
          }
        }
      }
    }
    frames.push_back(frame);
  };

  const auto count = [&](const pugi::xml_node& top, Part part) -> std::uint64_t {
    if (position(top) == facts_.size()) return 0;
    if (states[slot(top, part)] == State::kDone) return counts[slot(top, part)];
    open(top, part);
    std::uint64_t result = 0;
    while (!frames.empty()) {
      Frame& frame = frames.back();
      if (pending.size() > frame.first) {
        const Dependency next = pending.back();
        pending.pop_back();
        const std::size_t at = slot(next.node, next.part);
        if (states[at] == State::kDone) {
          frame.sum = saturating_add(frame.sum, counts[at]);
        } else if (states[at] == State::kNew) {
          open(next.node, next.part);  // may reallocate frames: `frame` is not used after this
        }
        // kCounting: a reference back into what is being counted, cut as the walk cuts it.
        continue;
      }
      const std::size_t at = slot(frame.node, frame.part);
      states[at] = State::kDone;
      counts[at] = frame.sum;
      const std::uint64_t finished = frame.sum;
      frames.pop_back();
      if (frames.empty()) {
        result = finished;
      } else {
        frames.back().sum = saturating_add(frames.back().sum, finished);
      }
    }
    return result;
  };

  // The root's children (the walk starts there: the root itself is not counted), then the content of each
  // mask, pattern and marker, as drawn once.
  std::uint64_t total = displayed(root) ? count(root, Part::kContent) : 0;
  for (const pugi::xml_node& resource : resources)
    total = saturating_add(total, count(resource, Part::kContent));
  return total;
}

}  // namespace curvescan::svg::detail
