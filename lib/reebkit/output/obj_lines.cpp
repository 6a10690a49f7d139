#include "reebkit/output/obj_lines.h"

#include "reebkit/core/error.h"

#include <string>

namespace reebkit {

ObjLinesWriter::ObjLinesWriter(std::ostream& out) : out_(out) { out_.precision(17); }

ObjLinesWriter& ObjLinesWriter::comment(std::string_view text) {
  if (text.find('\n') != std::string_view::npos) throw InvalidArgument("ObjLinesWriter: a comment holds a line break");
  out_ << "# " << text << "\n";
  return *this;
}

ObjLinesWriter& ObjLinesWriter::object(std::string_view name) {
  out_ << "o " << name << "\n";
  return *this;
}

Index ObjLinesWriter::point(const Vec3& p) {
  out_ << "v " << p.x() << " " << p.y() << " " << p.z() << "\n";
  return ++points_;
}

ObjLinesWriter& ObjLinesWriter::line(const std::vector<Index>& points) {
  if (points.size() < 2) throw InvalidArgument("ObjLinesWriter: a line needs two points or more");
  for (const Index p : points)
    if (p < 1 || p > points_)
      throw InvalidArgument("ObjLinesWriter: line through vertex " + std::to_string(p) + " of " +
                            std::to_string(points_) + " written");
  out_ << "l";
  for (const Index p : points) out_ << " " << p;
  out_ << "\n";
  return *this;
}

}  // namespace reebkit
