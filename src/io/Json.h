#pragma once
// Reading JSON input with the location of every value, so that each complaint names the file,
// the field and the problem in one line.
#include <nlohmann/json.hpp>
#include <string>

#include "mms/Errors.h"
#include "mms/Geometry.h"

namespace mms::json_in {

using Json = nlohmann::json;

constexpr int kMaxDepth = 64;
constexpr size_t kMaxFileBytes = size_t(256) << 20;

/// The whole of a file a user names: one-line InputErrors for a folder, an unreadable or
/// oversized (more than kMaxFileBytes) file.
std::string readFile(const std::string& path);
/// Reads and parses a whole file; rejects unreadable files, oversized files, syntax errors
/// and nesting deeper than kMaxDepth.
Json parseFile(const std::string& path);
/// The same for text already in memory (`source` names it in messages).
Json parseText(const std::string& text, const std::string& source);

/// A JSON value together with where it is: "robots[0].shape".
class Node {
 public:
  Node(const Json& value, std::string file, std::string where)
      : v_(&value), file_(std::move(file)), where_(std::move(where)) {}

  [[noreturn]] void fail(const std::string& problem) const;

  const Json& json() const { return *v_; }
  const std::string& where() const { return where_; }
  const std::string& file() const { return file_; }

  bool has(const char* key) const { return v_->is_object() && v_->contains(key); }
  Node operator[](const char* key) const;  // required member of an object
  Node operator[](size_t i) const;         // element of an array
  size_t size() const { return v_->size(); }

  void requireObject() const;
  /// Every member must be one of the allowed keys (catches typos such as "obstacle").
  void allowOnly(std::initializer_list<const char*> keys) const;
  size_t arraySize(size_t minSize, size_t maxSize) const;  // requires an array
  std::string string() const;
  /// A finite number with |value| <= limit.
  double number(double limit) const;
  Vec2 point(double limit) const;
  Ring ring(double limit, size_t maxVertices) const;

 private:
  const Json* v_;
  std::string file_, where_;
};

/// Largest coordinate magnitude accepted anywhere: beyond it double precision no longer
/// leaves room for the contact tolerance.
constexpr double kMaxCoordinate = 1e6;
constexpr double kMaxAngle = 1e4;
constexpr size_t kMaxVertices = 100000;

const char* typeName(const Json& j);

}  // namespace mms::json_in
