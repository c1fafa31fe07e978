#include "io/xdmf_writer.hpp"

#include <charconv>
#include <cstdint>
#include <cstdio>

#include "io/atomic_file.hpp"

namespace isphdem {

namespace {

std::string format_double(double v) {
  // Shortest round-trip text: ParaView's time equals the HDF5 attribute exactly.
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

// SnapshotWriter restricts names to [A-Za-z0-9_.-], but this is callable on its own.
std::string xml(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

const XdmfArray* find_array(const XdmfStep& s, const std::string& name) {
  for (const auto& a : s.arrays)
    if (a.name == name) return &a;
  return nullptr;
}

std::string dimensions(const XdmfStep& s, const XdmfArray& a) {
  return a.cols == 1 ? std::to_string(s.rows)
                     : std::to_string(s.rows) + " " + std::to_string(a.cols);
}

// XDMF 2 attribute types by component count; Matrix is the catch-all (ParaView reads it as an
// n-component array, e.g. quaternions with 4).
const char* attribute_type(std::size_t cols) {
  switch (cols) {
    case 1:
      return "Scalar";
    case 2:
    case 3:
      return "Vector";
    case 6:
      return "Tensor6";
    case 9:
      return "Tensor";
    default:
      return "Matrix";
  }
}

void append_data_item(std::string& out, const XdmfStep& s, const XdmfArray& a, const char* indent) {
  out += indent;
  out += "<DataItem Format=\"HDF\" NumberType=\"";
  out += a.floating ? "Float" : "Int";
  out += "\" Precision=\"" + std::to_string(a.bytes) + "\" Dimensions=\"" + dimensions(s, a) +
         "\">" + xml(s.file + ":/" + s.group + "/" + a.name) + "</DataItem>\n";
}

}  // namespace

bool XdmfStep::drawable() const {
  const XdmfArray* p = find_array(*this, "position");
  return rows > 0 && p && p->floating && (p->cols == 2 || p->cols == 3);
}

std::string xdmf_document(const std::string& name, const std::vector<XdmfStep>& steps) {
  std::string out =
      "<?xml version=\"1.0\" ?>\n"
      "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      "<Xdmf Version=\"2.0\">\n"
      " <Domain>\n"
      "  <Grid Name=\"" +
      xml(name) + "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& s : steps) {
    if (!s.drawable()) continue;
    const XdmfArray& position = *find_array(s, "position");
    char step_name[32];
    std::snprintf(step_name, sizeof step_name, "%08ld", s.step);
    out += "   <Grid Name=\"" + xml(name) + "_" + step_name + "\" GridType=\"Uniform\">\n";
    out += "    <Time Value=\"" + format_double(s.time) + "\"/>\n";
    out += "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" +
           std::to_string(s.rows) + "\" NodesPerElement=\"1\"/>\n";
    out += "    <Geometry GeometryType=\"";
    out += position.cols == 2 ? "XY" : "XYZ";
    out += "\">\n";
    append_data_item(out, s, position, "     ");
    out += "    </Geometry>\n";
    for (const auto& a : s.arrays) {
      if (&a == &position) continue;
      out += "    <Attribute Name=\"" + xml(a.name) + "\" AttributeType=\"" +
             attribute_type(a.cols) + "\" Center=\"Node\">\n";
      append_data_item(out, s, a, "     ");
      out += "    </Attribute>\n";
    }
    out += "   </Grid>\n";
  }
  out +=
      "  </Grid>\n"
      " </Domain>\n"
      "</Xdmf>\n";
  return out;
}

void write_xdmf(const std::filesystem::path& path, const std::string& name,
                const std::vector<XdmfStep>& steps) {
  write_file_atomically(path, xdmf_document(name, steps));
}

}  // namespace isphdem
