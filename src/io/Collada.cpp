#include "io/Collada.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <pugixml.hpp>
#include <sstream>

#include "mms/Errors.h"

namespace mms {

namespace {

using Matrix = std::array<double, 16>;  // row-major, as COLLADA writes <matrix>

Matrix identity() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix c{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) c[4 * i + j] += a[4 * i + k] * b[4 * k + j];
  return c;
}

std::vector<double> numbers(const std::string& file, const char* what, const char* text) {
  std::vector<double> v;
  std::istringstream in(text ? text : "");
  in.imbue(std::locale::classic());
  std::string tok;
  while (in >> tok) {
    char* end = nullptr;
    double x = std::strtod(tok.c_str(), &end);
    if (end == tok.c_str() || *end != '\0' || !std::isfinite(x))
      throw InputError(file + ": " + what + ": not a number: '" + tok + "'");
    v.push_back(x);
  }
  return v;
}

// A transform element's numbers, exactly `count` of them.
std::vector<double> fixedNumbers(const std::string& file, const pugi::xml_node& element,
                                 size_t count) {
  const std::string tag = std::string("<") + element.name() + ">";
  std::vector<double> v = numbers(file, tag.c_str(), element.child_value());
  if (v.size() != count)
    throw InputError(file + ": " + tag + ": expected " + std::to_string(count) + " numbers");
  return v;
}

class Reader {
 public:
  Reader(std::string file, const pugi::xml_document& doc) : file_(std::move(file)) {
    index(doc.document_element());
  }

  const pugi::xml_node& byId(const std::string& url, const char* what) const {
    std::string id = !url.empty() && url[0] == '#' ? url.substr(1) : url;
    auto it = ids_.find(id);
    if (it == ids_.end())
      throw InputError(file_ + ": " + what + ": no element with id '" + id + "'");
    return it->second;
  }

  void geometry(const pugi::xml_node& geom, const Matrix& m, ColladaMesh& out) const {
    for (pugi::xml_node mesh : geom.children("mesh")) {
      for (pugi::xml_node lines : mesh.children("lines")) (void)lines, ++out.lineElements;
      for (pugi::xml_node linestrips : mesh.children("linestrips"))
        (void)linestrips, ++out.lineElements;
      for (pugi::xml_node tris : mesh.children("triangles")) triangles(tris, m, out);
      if (mesh.child("polylist") || mesh.child("polygons"))
        throw InputError(file_ + ": <mesh>: polylist/polygons are not supported, only triangles");
    }
  }

 private:
  // Without recursion: a document nested a hundred thousand levels deep must not overflow the
  // stack (the fuzzer wrote one).
  void index(const pugi::xml_node& root) {
    std::vector<pugi::xml_node> todo{root};
    while (!todo.empty()) {
      const pugi::xml_node n = todo.back();
      todo.pop_back();
      if (auto id = n.attribute("id")) ids_.emplace(id.value(), n);
      for (pugi::xml_node c : n.children()) todo.push_back(c);
    }
  }

  // Positions of a <vertices> or <source> element: (x, y, z) triples. A <vertices> refers to a
  // source; references that loop are refused.
  std::vector<double> positions(const pugi::xml_node& input, int depth = 0) const {
    if (depth > 8)
      throw InputError(file_ + ": <vertices>: POSITION inputs refer to each other in a loop");
    pugi::xml_node src = byId(input.attribute("source").value(), "<input source>");
    if (std::string(src.name()) == "vertices") {
      for (pugi::xml_node in : src.children("input"))
        if (std::string(in.attribute("semantic").value()) == "POSITION")
          return positions(in, depth + 1);
      throw InputError(file_ + ": <vertices id='" + src.attribute("id").value() +
                       "'>: no POSITION input");
    }
    pugi::xml_node arr = src.child("float_array");
    std::vector<double> v = numbers(file_, "<float_array>", arr.child_value());
    size_t stride = 3;
    if (auto acc = src.child("technique_common").child("accessor"))
      stride = acc.attribute("stride").as_uint(3);
    if (stride < 3) throw InputError(file_ + ": <accessor>: stride under 3");
    std::vector<double> xyz;
    for (size_t i = 0; i + stride <= v.size(); i += stride) xyz.insert(xyz.end(), &v[i], &v[i] + 3);
    return xyz;
  }

  void triangles(const pugi::xml_node& tris, const Matrix& m, ColladaMesh& out) const {
    size_t stride = 0, vertexOffset = SIZE_MAX;
    std::vector<double> xyz;
    for (pugi::xml_node in : tris.children("input")) {
      size_t off = in.attribute("offset").as_uint(0);
      stride = std::max(stride, off + 1);
      if (std::string(in.attribute("semantic").value()) == "VERTEX") {
        vertexOffset = off;
        xyz = positions(in);
      }
    }
    if (vertexOffset == SIZE_MAX) throw InputError(file_ + ": <triangles>: no VERTEX input");
    std::vector<double> p = numbers(file_, "<triangles><p>", tris.child("p").child_value());
    const size_t count = xyz.size() / 3;
    // The plane of these files is the transformed mesh's X/Z.
    auto planar = [&](size_t i) {
      const double x = xyz[3 * i], y = xyz[3 * i + 1], z = xyz[3 * i + 2];
      const Vec2 v{m[0] * x + m[1] * y + m[2] * z + m[3], m[8] * x + m[9] * y + m[10] * z + m[11]};
      if (!std::isfinite(v.x) || !std::isfinite(v.y))
        throw InputError(file_ +
                         ": <triangles>: a vertex beyond the range of numbers once the "
                         "nodes' matrices are applied");
      return v;
    };
    for (size_t i = 0; i < count; ++i) {
      const Vec2 v = planar(i);
      const double n = double(++out.vertexCount);
      out.vertexMean = {out.vertexMean.x + (v.x - out.vertexMean.x) / n,
                        out.vertexMean.y + (v.y - out.vertexMean.y) / n};
    }
    auto project = [&](double idx) {
      // Range first: converting 1e92 to an integer is undefined (the fuzzer wrote one).
      if (!(idx >= 0 && idx < double(count)) || idx != std::floor(idx))
        throw InputError(file_ + ": <triangles><p>: vertex index " + std::to_string(idx) +
                         " out of range");
      return planar(size_t(idx));
    };
    const size_t per = 3 * stride;
    if (p.size() % per != 0)
      throw InputError(file_ + ": <triangles><p>: index count not 3 x inputs");
    for (size_t t = 0; t + per <= p.size(); t += per)
      out.triangles.push_back({project(p[t + vertexOffset]), project(p[t + stride + vertexOffset]),
                               project(p[t + 2 * stride + vertexOffset])});
  }

  std::string file_;
  std::map<std::string, pugi::xml_node> ids_;
};

void walk(const Reader& r, const pugi::xml_node& node, const Matrix& parent, ColladaMesh& out,
          int depth, const std::string& file) {
  if (depth > 64) throw InputError(file + ": <node>: nesting deeper than 64 (a cycle?)");
  Matrix m = parent;
  for (pugi::xml_node c : node.children()) {
    std::string name = c.name();
    Matrix local = identity();
    if (name == "matrix") {
      std::vector<double> v = fixedNumbers(file, c, 16);
      std::copy(v.begin(), v.end(), local.begin());
    } else if (name == "translate") {
      std::vector<double> v = fixedNumbers(file, c, 3);
      local[3] = v[0], local[7] = v[1], local[11] = v[2];
    } else if (name == "scale") {
      std::vector<double> v = fixedNumbers(file, c, 3);
      local[0] = v[0], local[5] = v[1], local[10] = v[2];
    } else if (name == "rotate") {
      throw InputError(file + ": <rotate>: not supported (use <matrix>)");
    } else {
      continue;
    }
    m = multiply(m, local);
  }
  for (pugi::xml_node c : node.children()) {
    std::string name = c.name();
    if (name == "instance_geometry")
      r.geometry(r.byId(c.attribute("url").value(), "<instance_geometry url>"), m, out);
    else if (name == "instance_node")
      walk(r, r.byId(c.attribute("url").value(), "<instance_node url>"), m, out, depth + 1, file);
    else if (name == "node")
      walk(r, c, m, out, depth + 1, file);
  }
}

}  // namespace

namespace {
ColladaMesh fromDocument(const pugi::xml_document& doc, const pugi::xml_parse_result& ok,
                         const std::string& file);
}  // namespace

ColladaMesh readColladaPlanar(const std::string& file) {
  pugi::xml_document doc;
  return fromDocument(doc, doc.load_file(file.c_str()), file);
}

ColladaMesh parseColladaPlanar(const std::string& text, const std::string& source) {
  pugi::xml_document doc;
  return fromDocument(doc, doc.load_buffer(text.data(), text.size()), source);
}

namespace {
ColladaMesh fromDocument(const pugi::xml_document& doc, const pugi::xml_parse_result& ok,
                         const std::string& file) {
  if (!ok)
    throw InputError(file + ": (XML, offset " + std::to_string(ok.offset) +
                     "): " + ok.description());
  pugi::xml_node root = doc.child("COLLADA");
  if (!root) throw InputError(file + ": (root): not a COLLADA document");
  Reader r(file, doc);
  ColladaMesh out;
  pugi::xml_node scene = root.child("scene").child("instance_visual_scene");
  pugi::xml_node visual = scene ? r.byId(scene.attribute("url").value(), "<instance_visual_scene>")
                                : root.child("library_visual_scenes").child("visual_scene");
  if (!visual) throw InputError(file + ": <library_visual_scenes>: no visual scene");
  for (pugi::xml_node n : visual.children("node")) walk(r, n, identity(), out, 0, file);
  return out;
}
}  // namespace

}  // namespace mms
