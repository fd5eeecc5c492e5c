#include "io/Json.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <unordered_set>

namespace mms::json_in {

const char* typeName(const Json& j) {
  switch (j.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::object:
      return "an object";
    case Json::value_t::array:
      return "an array";
    case Json::value_t::string:
      return "a string";
    case Json::value_t::boolean:
      return "a boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
      return "a number";
    default:
      return "an unsupported value";
  }
}

namespace {

struct TooDeep {};

// nlohmann's messages start with "[json.exception.parse_error.101] parse error at ...".
std::string cleanParseMessage(const std::string& what) {
  std::string m = what;
  if (auto p = m.find("] "); m.rfind("[json.exception", 0) == 0 && p != std::string::npos)
    m = m.substr(p + 2);
  for (char& c : m)
    if (c == '\n' || c == '\r') c = ' ';
  return m;
}

}  // namespace

namespace {

// Whether arrays and objects nest deeper than `limit` anywhere in `text` (brackets inside
// strings do not count). Scanned before parsing, so a hostile file never makes us build (or
// later recursively destroy) a deep tree. A parser callback could see the depth too, but its
// bookkeeping scans an object's parent each time the object ends: quadratic in a long array of
// objects (`mms view` with a 43 MB record of 205 000 manifolds: 15.4 s, against 3.7 s).
bool nestsDeeperThan(const std::string& text, int limit) {
  int depth = 0;
  bool inString = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\')
        ++i;  // the escaped character, whatever it is
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return true;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return false;
}

}  // namespace

namespace {

// nlohmann's DOM parser, with each object's keys checked for a second use: JSON allows a
// duplicate key and nlohmann keeps the last, so two "bounds" would silently drop the first.
// SAX rather than a parser callback, whose bookkeeping is quadratic in a long array of objects.
class NoDuplicateKeys {
 public:
  explicit NoDuplicateKeys(Json& out) : dom_(out) {}
  bool null() { return value(dom_.null()); }
  bool boolean(bool v) { return value(dom_.boolean(v)); }
  bool number_integer(Json::number_integer_t v) { return value(dom_.number_integer(v)); }
  bool number_unsigned(Json::number_unsigned_t v) { return value(dom_.number_unsigned(v)); }
  bool number_float(Json::number_float_t v, const std::string& s) {
    return value(dom_.number_float(v, s));
  }
  bool string(std::string& v) { return value(dom_.string(v)); }
  bool binary(Json::binary_t& v) { return value(dom_.binary(v)); }
  bool start_object(std::size_t n) {
    frames_.push_back({false, {}, {}, {}, 0});
    return dom_.start_object(n);
  }
  bool key(std::string& k) {
    Frame& f = frames_.back();
    if (f.seen(k)) throw Duplicate{where() + (frames_.size() > 1 ? "." : "") + k};
    f.key = k;
    return dom_.key(k);
  }
  bool end_object() { return close(dom_.end_object()); }
  bool start_array(std::size_t n) {
    frames_.push_back({true, {}, {}, {}, 0});
    return dom_.start_array(n);
  }
  bool end_array() { return close(dom_.end_array()); }
  template <class Exception>
  bool parse_error(std::size_t at, const std::string& token, const Exception& e) {
    return dom_.parse_error(at, token, e);
  }
  struct Duplicate {
    std::string where;
  };

 private:
  struct Frame {
    bool array;
    std::string key;                // an object's: the key being read
    std::vector<std::string> keys;  // an object's keys so far (a set past 32)
    std::unordered_set<std::string> many;
    size_t index;  // an array's: the element being read
    bool seen(const std::string& k) {
      if (many.empty() && keys.size() < 32) {
        for (const std::string& x : keys)
          if (x == k) return true;
        keys.push_back(k);
        return false;
      }
      if (many.empty()) many.insert(keys.begin(), keys.end());
      return !many.insert(k).second;
    }
  };
  bool value(bool ok) {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
    return ok;
  }
  bool close(bool ok) {
    frames_.pop_back();
    return value(ok);
  }
  // The JSON path of the object being read (robots[0].shape), as Node names fields.
  std::string where() const {
    std::string w;
    for (size_t i = 0; i + 1 < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      w += f.array ? "[" + std::to_string(f.index) + "]" : (w.empty() ? "" : ".") + f.key;
    }
    return w;
  }
  nlohmann::detail::json_sax_dom_parser<Json> dom_;
  std::vector<Frame> frames_;
};

}  // namespace

namespace {

/// Standard input, up to the size limit.
std::string readStandardInput() {
  std::string text;
  char buf[1 << 16];
  while (std::cin.read(buf, sizeof buf) || std::cin.gcount() > 0) {
    text.append(buf, size_t(std::cin.gcount()));
    if (text.size() > kMaxFileBytes)
      throw InputError("-: (file): standard input is larger than " +
                       std::to_string(kMaxFileBytes >> 20) + " MiB");
  }
  if (std::cin.bad()) throw InputError("-: (file): standard input: read failed");
  return text;
}

/// The offset of a byte no text file holds (NUL, or a control character other than tab,
/// newline, carriage return and form feed) among the first 4096, if any: such a file is a
/// picture, an archive or a program, and the JSON parser's complaint about its first byte would
/// not say so.
std::optional<size_t> binaryByte(const std::string& text) {
  const size_t n = std::min<size_t>(text.size(), 4096);
  for (size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f') return i;
  }
  return std::nullopt;
}

}  // namespace

Json parseText(const std::string& text, const std::string& source) {
  if (const auto at = binaryByte(text))
    throw InputError(source + ": (document): not a text file (byte " + std::to_string(*at) +
                     " is binary data), so not JSON");
  try {
    if (nestsDeeperThan(text, kMaxDepth)) throw TooDeep{};
    Json out;
    NoDuplicateKeys sax(out);
    Json::sax_parse(text, &sax);
    return out;
  } catch (const NoDuplicateKeys::Duplicate& d) {
    throw InputError(source + ": " + d.where + ": given twice (a key may appear once)");
  } catch (const TooDeep&) {
    throw InputError(source + ": (document): JSON nested deeper than " + std::to_string(kMaxDepth) +
                     " levels");
  } catch (const Json::exception& e) {  // syntax errors, and numbers beyond double range
    throw InputError(source + ": (document): not valid JSON: " + cleanParseMessage(e.what()));
  }
}

std::string readFile(const std::string& path) {
  if (path == "-") return readStandardInput();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path + ": (file): is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": (file): cannot open for reading");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw InputError(path + ": (file): cannot read (not a regular file?)");
  if (size_t(size) > kMaxFileBytes)
    throw InputError(path + ": (file): larger than " + std::to_string(kMaxFileBytes >> 20) +
                     " MiB");
  in.seekg(0);
  std::string text(size_t(size), '\0');
  if (!in.read(text.data(), size)) throw InputError(path + ": (file): read failed");
  return text;
}

Json parseFile(const std::string& path) { return parseText(readFile(path), path); }

void Node::fail(const std::string& problem) const {
  throw InputError(file_ + ": " + (where_.empty() ? "(document)" : where_) + ": " + problem);
}

Node Node::operator[](const char* key) const {
  requireObject();
  auto it = v_->find(key);
  const std::string w = where_.empty() ? std::string(key) : where_ + "." + key;
  if (it == v_->end()) Node(*v_, file_, w).fail("missing");
  return Node(*it, file_, w);
}

Node Node::operator[](size_t i) const {
  return Node((*v_)[i], file_, where_ + "[" + std::to_string(i) + "]");
}

void Node::requireObject() const {
  if (!v_->is_object()) fail(std::string("expected an object, found ") + typeName(*v_));
}

void Node::allowOnly(std::initializer_list<const char*> keys) const {
  requireObject();
  for (auto it = v_->begin(); it != v_->end(); ++it) {
    bool known = false;
    for (const char* k : keys) known = known || it.key() == k;
    if (!known) {
      std::string list;
      for (const char* k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
      Node(it.value(), file_, where_.empty() ? it.key() : where_ + "." + it.key())
          .fail("unknown field (expected one of: " + list + ")");
    }
  }
}

size_t Node::arraySize(size_t minSize, size_t maxSize) const {
  if (!v_->is_array()) fail(std::string("expected an array, found ") + typeName(*v_));
  const size_t n = v_->size();
  if (n < minSize || n > maxSize) {
    if (minSize == maxSize)
      fail("expected " + std::to_string(minSize) + " elements, found " + std::to_string(n));
    if (n < minSize)
      fail("expected at least " + std::to_string(minSize) + " elements, found " +
           std::to_string(n));
    fail("too many elements (" + std::to_string(n) + ", at most " + std::to_string(maxSize) + ")");
  }
  return n;
}

std::string Node::string() const {
  if (!v_->is_string()) fail(std::string("expected a string, found ") + typeName(*v_));
  return v_->get<std::string>();
}

double Node::number(double limit) const {
  if (!v_->is_number()) fail(std::string("expected a number, found ") + typeName(*v_));
  const double x = v_->get<double>();
  if (!std::isfinite(x)) fail("number is not finite");
  if (std::fabs(x) > limit) {
    std::ostringstream s;
    s << "number " << x << " is out of range (|value| must be at most " << limit << ")";
    fail(s.str());
  }
  return x;
}

Vec2 Node::point(double limit) const {
  arraySize(2, 2);
  return {(*this)[size_t(0)].number(limit), (*this)[size_t(1)].number(limit)};
}

Ring Node::ring(double limit, size_t maxVertices) const {
  const size_t n = arraySize(3, maxVertices);
  Ring r(n);
  for (size_t i = 0; i < n; ++i) r[i] = (*this)[i].point(limit);
  return r;
}

}  // namespace mms::json_in
