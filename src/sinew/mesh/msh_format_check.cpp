#include "sinew/mesh/msh_format_check.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>
#include <vector>

#include "sinew/core/error.hpp"
#include "sinew/mesh/msh_cursor.hpp"

namespace sinew::mesh {

namespace {

/// The section names of the MSH format (Gmsh reference manual, "MSH file format"); a line
/// holding one of them opens that section.
constexpr std::array<const char*, 13> kSectionNames = {
    "MeshFormat",  "PhysicalNames",   "Entities", "PartitionedEntities", "Nodes",
    "Elements",    "Periodic",        "GhostElements", "Parametrizations", "NodeData",
    "ElementData", "ElementNodeData", "InterpolationScheme"};

bool is_section_opener(const std::string& line) {
  if (line.size() < 2 || line[0] != '$') return false;
  for (const char* name : kSectionNames) {
    if (line.compare(1, std::string::npos, name) == 0) return true;
  }
  return false;
}

/// Nodes per element of the MSH element types up to 19 (Gmsh reference manual, "MSH file
/// format", element types); 0 for types not listed.
int nodes_of_element_type(std::uint64_t type) {
  constexpr std::array<int, 20> kNodes = {0, 2, 3,  4,  4,  8,  6,  5,  3,  6,
                                          9, 10, 27, 18, 14, 1, 8, 20, 15, 13};
  return type < kNodes.size() ? kNodes[type] : 0;
}

MshFileFormat read_format(MshCursor& cursor) {
  const std::string not_msh =
      " is not a Gmsh MSH file (it must begin with a $MeshFormat line; sinew never runs Gmsh "
      "scripts such as .geo files: mesh the geometry in Gmsh and save it as .msh)";
  std::string line;
  if (!cursor.next_line(line) || line != "$MeshFormat") cursor.fail(not_msh);
  if (!cursor.next_line(line)) cursor.fail(not_msh);
  std::istringstream fields(line);
  std::string version_text;
  int file_type = -1;
  int data_size = -1;
  std::string extra;
  fields >> version_text >> file_type >> data_size;
  const bool parsed = !fields.fail() && !(fields >> extra);
  MshFileFormat format;
  format.version = version_text == "2.2" ? 2.2 : version_text == "4" || version_text == "4.0" ? 4.0
                                             : version_text == "4.1"                         ? 4.1
                                                                                             : 0;
  if (!parsed || format.version == 0 || (file_type != 0 && file_type != 1) || data_size != 8) {
    cursor.fail(" has the $MeshFormat header \"" + line.substr(0, 60) +
                "\"; sinew reads MSH versions 2.2, 4.0 and 4.1, ASCII (0) or binary (1), with "
                "data size 8, e.g. \"4.1 0 8\" (re-export it from Gmsh)");
  }
  format.binary = file_type == 1;
  if (format.binary && format.version == 4.0) {
    cursor.fail(" is a binary MSH 4.0 file, which sinew does not read; re-export it from Gmsh as "
                "MSH 4.1 (Mesh.MshFileVersion = 4.1) or as ASCII");
  }
  if (format.binary) {
    const int one = cursor.binary<int>("MeshFormat");
    if (one != 1) {
      cursor.fail(" is a binary MSH file of another byte order (or damaged); re-export it from "
                  "Gmsh as ASCII (Mesh.Binary = 0)");
    }
  }
  return format;
}

/// The first line of a version 4 $Nodes or $Elements section: the number of entity blocks and
/// of items (4.1 adds the smallest and largest tag, skipped here).
struct V4SectionHeader {
  std::uint64_t blocks = 0;
  std::uint64_t items = 0;
};

V4SectionHeader read_v4_header(MshCursor& cursor, bool binary, bool v40, const std::string& section) {
  V4SectionHeader header;
  header.blocks = cursor.v4_count(binary, section);
  header.items = cursor.v4_count(binary, section);
  if (!v40) {
    cursor.v4_count(binary, section);  // min tag
    cursor.v4_count(binary, section);  // max tag
  }
  return header;
}

/// Walks a version 4.0 (ASCII) or 4.1 $Nodes section up to its last coordinate, checking every
/// count; appends the node tags to `tags`. Version 4.1 gives each entity block's tags, then
/// its coordinates; 4.0 a tag before each node's coordinates, and fewer header fields.
void walk_nodes_v4(MshCursor& cursor, bool binary, bool v40, std::vector<std::uint64_t>& tags) {
  const std::string section = "Nodes";
  const auto count = [&] { return cursor.v4_count(binary, section); };
  const auto small = [&] { return cursor.v4_small(binary, section); };
  const auto [num_blocks, num_nodes] = read_v4_header(cursor, binary, v40, section);
  cursor.check_fits(num_blocks, binary ? 20 : 8, "entity blocks", section);
  cursor.check_fits(num_nodes, binary ? 32 : 8, "nodes", section);
  for (std::uint64_t b = 0; b < num_blocks; ++b) {
    const std::uint64_t first = small();   // 4.1: entity dimension; 4.0: entity tag
    const std::uint64_t second = small();  // 4.1: entity tag; 4.0: entity dimension
    const std::uint64_t dim = v40 ? second : first;
    const std::uint64_t parametric = small();
    const std::uint64_t block_nodes = count();
    if (dim > 3 || parametric > 1) {
      cursor.fail(" is malformed: a $Nodes entity block has dimension " + std::to_string(dim) +
                  " and parametric flag " + std::to_string(parametric) +
                  " (expected 0-3 and 0 or 1)");
    }
    const std::uint64_t values_per_node = 3 + (parametric ? dim : 0);
    cursor.check_fits(block_nodes, binary ? 8 * (1 + values_per_node) : 2 * (1 + values_per_node),
                      "nodes in an entity block", section);
    if (v40) {
      for (std::uint64_t i = 0; i < block_nodes; ++i) {
        tags.push_back(count());
        cursor.skip_tokens(values_per_node, section);
      }
      continue;
    }
    for (std::uint64_t i = 0; i < block_nodes; ++i) tags.push_back(count());
    if (binary) {
      cursor.skip_bytes(block_nodes * 8 * values_per_node, section);
    } else {
      cursor.skip_tokens(block_nodes * values_per_node, section);
    }
  }
}

/// Walks a version 2.2 $Nodes section after its count, appending the node tags to `tags`.
void walk_nodes_v22(MshCursor& cursor, bool binary, std::uint64_t num_nodes,
                    std::vector<std::uint64_t>& tags) {
  const std::string section = "Nodes";
  for (std::uint64_t i = 0; i < num_nodes; ++i) {
    if (binary) {
      tags.push_back(static_cast<std::uint32_t>(cursor.binary<std::int32_t>(section)));
      cursor.skip_bytes(24, section);
    } else {
      tags.push_back(cursor.ascii_count(section));
      cursor.skip_tokens(3, section);
    }
  }
}

/// Throws InputError naming the first node tags that `tags` holds more than once: Gmsh would
/// keep one of the nodes and silently drop the other.
void reject_duplicate_tags(MshCursor& cursor, std::vector<std::uint64_t>& tags) {
  std::sort(tags.begin(), tags.end());
  std::vector<std::uint64_t> duplicates;
  for (std::size_t i = 0; i + 1 < tags.size(); ++i) {
    if (tags[i] == tags[i + 1] && (duplicates.empty() || duplicates.back() != tags[i])) {
      duplicates.push_back(tags[i]);
    }
  }
  if (duplicates.empty()) return;
  std::string listed;
  for (std::size_t i = 0; i < std::min<std::size_t>(duplicates.size(), 3); ++i) {
    listed += (i ? ", " : "") + std::to_string(duplicates[i]);
  }
  cursor.fail(": duplicate node tag" + std::string(duplicates.size() == 1 ? " " : "s ") + listed +
              (duplicates.size() > 3 ? ", ..." : "") + " (" + std::to_string(duplicates.size()) +
              (duplicates.size() == 1 ? " tag is" : " tags are") +
              " given to more than one node in $Nodes); every node needs its own tag");
}

/// The node tags of the $Nodes sections read so far, sorted, to check the nodes of elements.
class NodeTags {
 public:
  explicit NodeTags(std::vector<std::uint64_t> sorted) : sorted_(std::move(sorted)) {}
  /// Throws InputError unless `tag`, a node of element `element`, is a node tag.
  void check(MshCursor& cursor, std::uint64_t element, std::uint64_t tag) const {
    if (std::binary_search(sorted_.begin(), sorted_.end(), tag)) return;
    cursor.fail(" is malformed: element " + std::to_string(element) + " refers to node tag " +
                std::to_string(tag) + ", which its $Nodes section does not define");
  }

 private:
  std::vector<std::uint64_t> sorted_;
};

/// Throws InputError unless `type` is an element type of nodes_of_element_type(); Gmsh 4.8
/// aborts on types it does not know.
int checked_nodes_of_element_type(MshCursor& cursor, std::uint64_t type) {
  const int nodes = nodes_of_element_type(type);
  if (nodes == 0) {
    cursor.fail(" holds elements of type " + std::to_string(type) +
                ", which sinew does not read (it reads Gmsh element types 1-19; its meshes are "
                "linear tetrahedra, type 4)");
  }
  return nodes;
}

/// Walks a version 4.0 (ASCII) or 4.1 $Elements section, checking every count, element type
/// and node tag.
void walk_elements_v4(MshCursor& cursor, bool binary, bool v40, const NodeTags& nodes,
                      std::vector<std::uint64_t>& element_tags) {
  const std::string section = "Elements";
  const auto count = [&] { return cursor.v4_count(binary, section); };
  const auto small = [&] { return cursor.v4_small(binary, section); };
  const auto [num_blocks, num_elements] = read_v4_header(cursor, binary, v40, section);
  cursor.check_fits(num_blocks, binary ? 20 : 8, "entity blocks", section);
  cursor.check_fits(num_elements, binary ? 16 : 4, "elements", section);
  for (std::uint64_t b = 0; b < num_blocks; ++b) {
    small();  // entity dimension (4.1) or tag (4.0)
    small();  // entity tag (4.1) or dimension (4.0)
    const std::uint64_t type = small();
    const std::uint64_t block_elements = count();
    const int num_element_nodes = checked_nodes_of_element_type(cursor, type);
    const auto values_per_element = 1 + static_cast<std::uint64_t>(num_element_nodes);
    cursor.check_fits(block_elements, binary ? 8 * values_per_element : 2 * values_per_element,
                      "elements in an entity block", section);
    for (std::uint64_t e = 0; e < block_elements; ++e) {
      const std::uint64_t element = count();
      element_tags.push_back(element);
      for (int k = 0; k < num_element_nodes; ++k) nodes.check(cursor, element, count());
    }
  }
}

/// Walks a version 2.2 $Elements section after its count of `num_elements`, checking the counts
/// of binary blocks, every element type and every node tag.
void walk_elements_v22(MshCursor& cursor, bool binary, std::uint64_t num_elements,
                       const NodeTags& nodes, std::vector<std::uint64_t>& element_tags) {
  const std::string section = "Elements";
  const auto value = [&] {
    if (!binary) return cursor.ascii_count(section);
    return static_cast<std::uint64_t>(static_cast<std::uint32_t>(cursor.binary<std::int32_t>(section)));
  };
  std::uint64_t read = 0;
  while (read < num_elements) {
    // Binary: blocks of elements of one type "type count num-tags"; ASCII: one per line.
    std::uint64_t type = 0;
    std::uint64_t block_elements = 1;
    std::uint64_t num_tags = 0;
    if (binary) {
      type = value();
      block_elements = value();
      num_tags = value();
      if (block_elements == 0 || block_elements > num_elements - read) {
        cursor.fail(" is malformed: a block of its $Elements section holds " +
                    std::to_string(block_elements) + " elements, but only " +
                    std::to_string(num_elements - read) + " remain of the count in its header");
      }
    }
    const int num_element_nodes = binary ? checked_nodes_of_element_type(cursor, type) : 0;
    if (binary) {
      const auto ints_per_element = 1 + num_tags + static_cast<std::uint64_t>(num_element_nodes);
      cursor.check_fits(block_elements, 4 * ints_per_element, "elements in a block", section);
    }
    for (std::uint64_t e = 0; e < block_elements; ++e) {
      const std::uint64_t element = value();
      element_tags.push_back(element);
      if (!binary) {
        type = value();
        num_tags = value();
        cursor.check_fits(num_tags, 2, "tags of an element", section);
      }
      const int count = checked_nodes_of_element_type(cursor, type);
      cursor.check_fits(num_tags, 1, "tags of an element", section);
      for (std::uint64_t t = 0; t < num_tags; ++t) value();
      for (int k = 0; k < count; ++k) nodes.check(cursor, element, value());
    }
    read += block_elements;
  }
}

/// Checks a $PhysicalNames section (ASCII in every version): a count, then that many lines
/// "<dimension 0-3> <tag> \"<name>\"".
void check_physical_names(MshCursor& cursor) {
  const std::string section = "PhysicalNames";
  const std::uint64_t num_names = cursor.ascii_count(section);
  cursor.check_fits(num_names, 6, "physical names", section);
  std::string line;
  cursor.next_line(line);  // the rest of the count's line
  for (std::uint64_t i = 0; i < num_names; ++i) {
    if (!cursor.next_line(line)) cursor.truncated(section);
    std::istringstream fields(line);
    int dim = -1;
    long long tag = 0;
    std::string name;
    fields >> dim >> tag >> std::ws;
    std::getline(fields, name);
    if (fields.bad() || dim < 0 || dim > 3 || tag <= 0 || tag > 2147483647 || name.size() < 2 ||
        name.front() != '"' || name.back() != '"') {
      cursor.fail(" is malformed: its $PhysicalNames section holds the line \"" +
                  line.substr(0, 60) + "\" where \"<dimension 0-3> <positive tag> \\\"<name>\\\"\" belongs");
    }
  }
}

/// Checks a $NodeData, $ElementData or $ElementNodeData section (Gmsh reference manual, "MSH
/// file format"): counted string, real and integer tags (ASCII), the integer tags being the
/// time step, the number of components and the number of entities; then per entity its tag,
/// (for $ElementNodeData) its number of nodes, and the values, as text or binary. Gmsh 4.8
/// allocates from these counts and crashes or exhausts memory on wrong ones, or indexes its
/// storage with an entity tag: each must be in `sorted_tags` (of the nodes for $NodeData, of
/// the elements otherwise).
void check_data_section(MshCursor& cursor, const std::string& section, bool binary,
                        const std::vector<std::uint64_t>& sorted_tags) {
  const bool per_element_node = section == "ElementNodeData";
  const std::uint64_t num_strings = cursor.ascii_count(section);
  cursor.check_fits(num_strings, 2, "string tags", section);
  std::string line;
  cursor.skip_line();
  for (std::uint64_t i = 0; i < num_strings; ++i) {
    if (!cursor.next_line(line)) cursor.truncated(section);
  }
  const std::uint64_t num_reals = cursor.ascii_count(section);
  cursor.check_fits(num_reals, 2, "real tags", section);
  cursor.skip_tokens(num_reals, section);
  const std::uint64_t num_integers = cursor.ascii_count(section);
  cursor.check_fits(num_integers, 2, "integer tags", section);
  std::vector<std::uint64_t> integers;
  for (std::uint64_t i = 0; i < num_integers; ++i) integers.push_back(cursor.ascii_count(section));
  if (integers.size() < 3) return;  // Gmsh reports the missing tags
  const std::uint64_t components = integers[1];
  const std::uint64_t entities = integers[2];
  if (components == 0 || components > 9) {
    cursor.fail(" is malformed: its $" + section + " section has " + std::to_string(components) +
                " components per value (Gmsh data have 1 to 9)");
  }
  cursor.check_fits(entities, binary ? 4 + 8 * components : 2 * (1 + components), "values", section);
  if (binary) cursor.skip_line();  // binary data start on the next line
  for (std::uint64_t e = 0; e < entities; ++e) {
    std::uint64_t nodes = 1;
    std::uint64_t tag = 0;
    if (binary) {
      tag = static_cast<std::uint32_t>(cursor.binary<std::int32_t>(section));
      if (per_element_node) nodes = static_cast<std::uint32_t>(cursor.binary<std::int32_t>(section));
    } else {
      tag = cursor.ascii_count(section);
      if (per_element_node) nodes = cursor.ascii_count(section);
    }
    if (!std::binary_search(sorted_tags.begin(), sorted_tags.end(), tag)) {
      cursor.fail(" is malformed: its $" + section + " section gives a value for " +
                  (section == "NodeData" ? "node" : "element") + " tag " + std::to_string(tag) +
                  ", which the mesh does not define");
    }
    cursor.check_fits(nodes, binary ? 8 * components : 2 * components, "nodes of an element", section);
    if (binary) {
      cursor.skip_bytes(8 * nodes * components, section);
    } else {
      cursor.skip_tokens(nodes * components, section);
    }
  }
}

/// Checks an $InterpolationScheme section (ASCII in every version; Gmsh writes one with
/// post-processing views): a quoted name, a count of element topologies, and for each a
/// topology number, a count of matrices and each matrix as "<rows> <columns>" and its values.
/// Gmsh 4.8 aborts on a negative matrix size.
void check_interpolation_scheme(MshCursor& cursor) {
  const std::string section = "InterpolationScheme";
  std::string name;
  cursor.next_line(name);
  const std::uint64_t num_topologies = cursor.ascii_count(section);
  cursor.check_fits(num_topologies, 4, "element topologies", section);
  for (std::uint64_t t = 0; t < num_topologies; ++t) {
    cursor.ascii_count(section);  // topology
    const std::uint64_t num_matrices = cursor.ascii_count(section);
    cursor.check_fits(num_matrices, 4, "interpolation matrices", section);
    for (std::uint64_t m = 0; m < num_matrices; ++m) {
      const std::uint64_t rows = cursor.ascii_count(section);
      const std::uint64_t columns = cursor.ascii_count(section);
      cursor.check_fits(rows, 2, "matrix rows", section);
      cursor.check_fits(columns, 2, "matrix columns", section);
      if (rows > 0) cursor.check_fits(columns, 2 * rows, "matrix columns (times its rows)", section);
      cursor.skip_tokens(rows * columns, section);
    }
  }
}

/// Walks a version 4.0 (ASCII) or 4.1 $Entities section, checking every count: numbers of
/// points, curves, surfaces and volumes, then each entity's tag, coordinates (a point's 3 in
/// 4.1, a bounding box's 6 otherwise), physical tags and (curves and up) bounding entities.
void walk_entities_v4(MshCursor& cursor, bool binary, bool v40) {
  const std::string section = "Entities";
  const auto count = [&] {
    return binary ? cursor.binary<std::uint64_t>(section) : cursor.ascii_count(section);
  };
  const auto skip_ints = [&](std::uint64_t n) {
    if (binary) {
      cursor.skip_bytes(4 * n, section);
    } else {
      cursor.skip_tokens(n, section);
    }
  };
  const auto skip_doubles = [&](std::uint64_t n) {
    if (binary) {
      cursor.skip_bytes(8 * n, section);
    } else {
      cursor.skip_tokens(n, section);
    }
  };
  std::array<std::uint64_t, 4> num_entities{};
  for (auto& n : num_entities) {
    n = count();
    cursor.check_fits(n, binary ? 20 : 8, "entities", section);
  }
  for (int dim = 0; dim < 4; ++dim) {
    for (std::uint64_t e = 0; e < num_entities[static_cast<std::size_t>(dim)]; ++e) {
      skip_ints(1);  // tag
      skip_doubles(dim == 0 && !v40 ? 3 : 6);
      const std::uint64_t num_physicals = count();
      cursor.check_fits(num_physicals, binary ? 4 : 2, "physical tags of an entity", section);
      skip_ints(num_physicals);
      if (dim == 0) continue;
      const std::uint64_t num_bounding = count();
      cursor.check_fits(num_bounding, binary ? 4 : 2, "bounding entities of an entity", section);
      skip_ints(num_bounding);
    }
  }
}

/// Checks a $Nodes section (every count) and appends its node tags to `tags`.
void check_nodes_section(MshCursor& cursor, const MshFileFormat& format,
                         std::vector<std::uint64_t>& tags) {
  const std::string section = "Nodes";
  if (format.version >= 4.0) {
    return walk_nodes_v4(cursor, format.binary, format.version == 4.0, tags);
  }
  // Version 2.2: an ASCII count, then a node (tag and 3 coordinates, 28 bytes in binary).
  const std::uint64_t num_nodes = cursor.ascii_count(section);
  if (format.binary) cursor.skip_line();  // binary data start on the next line
  cursor.check_fits(num_nodes, format.binary ? 28 : 8, "nodes", section);
  walk_nodes_v22(cursor, format.binary, num_nodes, tags);
}

/// Checks an $Elements section: every count and element type, and that its elements' nodes
/// are in `nodes`.
void check_elements_section(MshCursor& cursor, const MshFileFormat& format, const NodeTags& nodes,
                            std::vector<std::uint64_t>& element_tags) {
  const std::string section = "Elements";
  if (format.version >= 4.0) {
    return walk_elements_v4(cursor, format.binary, format.version == 4.0, nodes, element_tags);
  }
  const std::uint64_t num_elements = cursor.ascii_count(section);
  if (format.binary) cursor.skip_line();
  cursor.check_fits(num_elements, 8, "elements", section);
  walk_elements_v22(cursor, format.binary, num_elements, nodes, element_tags);
}

}  // namespace

void check_msh_path(const std::string& path) {
  const std::string context = "mesh file \"" + path + "\"";
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status)) throw InputError(context + " does not exist");
  if (!std::filesystem::is_regular_file(status)) {
    throw InputError(context + " is not a regular file (a directory, FIFO or device); give the "
                               "path of a .msh file");
  }
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension != ".msh") {
    throw InputError(context + " has the extension \"" + extension +
                     "\"; sinew reads only Gmsh MSH files named *.msh (it never runs Gmsh "
                     "scripts such as .geo files: mesh the geometry in Gmsh and save it as .msh)");
  }
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error) throw InputError(context + " cannot be read: " + error.message());
  if (size > kMaxMshFileBytes) {
    throw InputError(context + " is " + std::to_string(size) +
                     " bytes long; sinew reads mesh files of at most " +
                     std::to_string(kMaxMshFileBytes) +
                     " bytes (2 GiB): save the mesh in binary (Mesh.Binary = 1) or coarsen it");
  }
}

MshFileFormat check_msh_content(const std::string& path, const std::string& shown_path) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error || size > kMaxMshFileBytes) {
    throw InputError("mesh file \"" + shown_path + "\" cannot be read" +
                     (error ? ": " + error.message() : std::string(" (it grew past 2 GiB)")));
  }
  MshCursor cursor(path, size, shown_path);
  const MshFileFormat format = read_format(cursor);
  std::map<std::string, int> sections_seen;
  std::vector<std::uint64_t> tags;          // of every node in $Nodes, sorted
  std::vector<std::uint64_t> element_tags;  // of every element in $Elements, sorted
  std::string line;
  std::string open = "MeshFormat";  // the section being read, "" between sections
  while (cursor.next_line(line)) {
    if (!open.empty()) {
      if (line == "$End" + open) {
        open.clear();
      } else if (is_section_opener(line)) {
        cursor.fail(": its $" + open + " section is not closed by $End" + open +
                    " before " + line + " (is the file truncated or edited?)");
      }
      continue;
    }
    if (!is_section_opener(line)) continue;  // Gmsh skips text between sections
    open = line.substr(1);
    ++sections_seen[open];
    if (open == "PhysicalNames") {
      check_physical_names(cursor);
    } else if (open == "NodeData" || open == "ElementData" || open == "ElementNodeData") {
      check_data_section(cursor, open, format.binary, open == "NodeData" ? tags : element_tags);
    } else if (open == "InterpolationScheme") {
      check_interpolation_scheme(cursor);
    } else if (open == "Entities" && format.version >= 4.0) {
      walk_entities_v4(cursor, format.binary, format.version == 4.0);
    } else if (open == "Nodes") {
      check_nodes_section(cursor, format, tags);
      reject_duplicate_tags(cursor, tags);  // sorts them
    } else if (open == "Elements") {
      if (!sections_seen.count("Nodes")) {
        cursor.fail(": its $Elements section comes before $Nodes; the nodes must come first");
      }
      check_elements_section(cursor, format, NodeTags(tags), element_tags);
      std::sort(element_tags.begin(), element_tags.end());
    }
  }
  if (!open.empty()) {
    cursor.fail(": its $" + open + " section is not closed by $End" + open +
                " (the file is truncated)");
  }
  for (const char* required : {"Nodes", "Elements"}) {
    if (!sections_seen.count(required)) {
      cursor.fail(" has no $" + std::string(required) +
                  " section; a volume mesh needs $Nodes and $Elements (mesh it in 3D in Gmsh)");
    }
  }
  return format;
}

MshFileFormat check_msh_file(const std::string& path) {
  check_msh_path(path);
  return check_msh_content(path, path);
}

}  // namespace sinew::mesh
