// Custom properties of one element (custom_properties.h).
#include "custom_properties.h"

#include <algorithm>
#include <optional>
#include <unordered_map>

#include "curvescan/svg/number.h"
#include "syntax.h"

namespace curvescan::svg::css {
namespace {

using Entry = CustomProperties::Entry;

bool by_name(const std::shared_ptr<const Entry>& entry, std::string_view name) {
  return entry->name < name;
}

// A declared value that holds var(): a node of the dependency graph (section 2.3).
struct Node {
  std::string_view name;
  std::string_view value;
  std::vector<std::size_t> edges;  // nodes it references
  // Tarjan's bookkeeping.
  std::size_t index = 0, low_link = 0;
  bool visited = false, on_stack = false;
  bool in_cycle = false;
};

// Tarjan's algorithm over `nodes`, iteratively. Marks the nodes of every cycle (a component of more than
// one node, or one that references itself) and returns the nodes in the order their components complete:
// every node comes after the nodes it references (outside its own component).
std::vector<std::size_t> dependency_order(std::vector<Node>& nodes) {
  std::vector<std::size_t> order, stack;
  std::size_t next_index = 0;
  struct Frame {
    std::size_t node, edge;
  };
  std::vector<Frame> calls;
  for (std::size_t root = 0; root < nodes.size(); ++root) {
    if (nodes[root].visited) continue;
    calls.push_back({root, 0});
    while (!calls.empty()) {
      Frame& frame = calls.back();
      Node& node = nodes[frame.node];
      if (frame.edge == 0 && !node.visited) {
        node.visited = true;
        node.index = node.low_link = next_index++;
        stack.push_back(frame.node);
        node.on_stack = true;
      }
      if (frame.edge < node.edges.size()) {
        const std::size_t target = node.edges[frame.edge++];
        if (target == frame.node) node.in_cycle = true;  // a reference to itself
        if (!nodes[target].visited) {
          calls.push_back({target, 0});  // `frame` and `node` are not used after this
        } else if (nodes[target].on_stack) {
          node.low_link = std::min(node.low_link, nodes[target].index);
        }
        continue;
      }
      // All edges done: a root closes its component.
      const std::size_t finished = frame.node;
      calls.pop_back();
      if (!calls.empty()) {
        Node& caller = nodes[calls.back().node];
        caller.low_link = std::min(caller.low_link, nodes[finished].low_link);
      }
      if (nodes[finished].low_link == nodes[finished].index) {
        const auto begin = std::find(stack.begin(), stack.end(), finished);
        const bool cycle = stack.end() - begin > 1;
        for (auto it = begin; it != stack.end(); ++it) {
          nodes[*it].on_stack = false;
          if (cycle) nodes[*it].in_cycle = true;
          order.push_back(*it);
        }
        stack.erase(begin, stack.end());
      }
    }
  }
  return order;
}

}  // namespace

const std::string* CustomProperties::find(std::string_view name) const noexcept {
  const auto it = std::lower_bound(entries_.begin(), entries_.end(), name, by_name);
  return it != entries_.end() && (*it)->name == name ? &(*it)->value : nullptr;
}

// Builds one element's set from its parent's (friend of CustomProperties).
class CustomPropertiesBuilder {
 public:
  explicit CustomPropertiesBuilder(const std::shared_ptr<const CustomProperties>& parent) {
    if (parent) entries_ = parent->entries_;
  }

  const std::string* find(std::string_view name) const {
    const auto it = std::lower_bound(entries_.begin(), entries_.end(), name, by_name);
    return it != entries_.end() && (*it)->name == name ? &(*it)->value : nullptr;
  }

  // Sets `name` to `value`, or removes it (nullopt: the guaranteed-invalid value). False when the set is
  // full and `name` is not in it.
  bool set(std::string_view name, std::optional<std::string> value) {
    const auto it = std::lower_bound(entries_.begin(), entries_.end(), name, by_name);
    const bool present = it != entries_.end() && (*it)->name == name;
    if (!value) {
      if (present) entries_.erase(it);
      return true;
    }
    auto entry = std::make_shared<const Entry>(Entry{std::string(name), std::move(*value)});
    if (present) {
      *it = std::move(entry);
      return true;
    }
    if (entries_.size() >= kMaxCustomProperties) return false;
    entries_.insert(it, std::move(entry));
    return true;
  }

  // Whether `name` has or can take a place in the set.
  bool can_hold(std::string_view name) const { return entries_.size() < kMaxCustomProperties || find(name); }

  std::shared_ptr<const CustomProperties> build() {
    auto set = std::make_shared<CustomProperties>();
    set->entries_ = std::move(entries_);
    return set;
  }

 private:
  std::vector<std::shared_ptr<const Entry>> entries_;
};

std::shared_ptr<const CustomProperties> compute_custom_properties(
    const std::shared_ptr<const CustomProperties>& parent, const std::vector<CustomDeclaration>& declarations,
    SubstitutionBudget& budget, std::vector<std::string>& warnings) {
  // The winning declaration of each name: the last one in cascade order.
  std::unordered_map<std::string_view, std::string_view> winners;
  std::vector<std::string_view> names;  // in order of first declaration, for warnings in source order
  for (const CustomDeclaration& declaration : declarations) {
    if (winners.insert_or_assign(declaration.name, declaration.value).second)
      names.push_back(declaration.name);
  }
  CustomPropertiesBuilder builder(parent);
  bool full = false;
  const auto set = [&](std::string_view name, std::optional<std::string> value) {
    if (!builder.set(name, std::move(value)) && !full) {
      full = true;
      warnings.push_back("more than " + std::to_string(kMaxCustomProperties) +
                         " custom properties on one element; '" + std::string(name) +
                         "' and later ones are dropped");
    }
  };
  // Step 1: CSS-wide keywords and values without var(); the others become nodes of the graph.
  std::vector<Node> nodes;
  std::unordered_map<std::string_view, std::size_t> node_of;
  for (const std::string_view name : names) {
    const std::string_view value = winners[name];
    const std::string_view trimmed = trim_whitespace(value);
    if (trimmed.size() <= 12) {
      const std::string keyword = ascii_lower(trimmed);
      if (keyword == "initial") {
        set(name, std::nullopt);
        continue;
      }
      if (keyword == "inherit" || keyword == "unset" || keyword == "revert" || keyword == "revert-layer")
        continue;  // the parent's value, already in the builder
    }
    if (!contains_var(value)) {
      set(name, std::string(value));
      continue;
    }
    node_of.emplace(name, nodes.size());
    nodes.push_back(Node{name, value, {}});
  }
  if (nodes.empty()) return builder.build();
  // Step 2: the edges (to declared values with var() only: any other value has none to follow).
  for (Node& node : nodes) {
    for (const std::string& reference : var_references(node.value)) {
      if (const auto found = node_of.find(reference); found != node_of.end())
        node.edges.push_back(found->second);
    }
  }
  const std::vector<std::size_t> order = dependency_order(nodes);
  // Step 3: in dependency order, so that every reference to a node is to a computed value.
  for (const std::size_t index : order) {
    const Node& node = nodes[index];
    if (!builder.can_hold(node.name)) {  // the set is full: dropped with the one warning `set` gives
      set(node.name, std::string());
      continue;
    }
    if (node.in_cycle) {
      warnings.push_back("custom property '" + std::string(node.name) +
                         "' is part of a var() reference cycle: it has no value");
      set(node.name, std::nullopt);
      continue;
    }
    Substitution substituted = substitute_var(
        node.value, [&builder](std::string_view name) { return builder.find(name); }, budget);
    if (!substituted.value) {
      warnings.push_back("custom property '" + std::string(node.name) + "': " + describe(substituted) +
                         ": it has no value");
      set(node.name, std::nullopt);
      continue;
    }
    set(node.name, std::move(substituted.value));
  }
  return builder.build();
}

}  // namespace curvescan::svg::css
