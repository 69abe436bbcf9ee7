#include <cairn/multibody/urdf_xml_check.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>

#include <tinyxml.h>

#include <cairn/common/number_text.h>

namespace cairn::multibody::internal {
namespace {

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

// An attribute value as it appears in a message: quoted, and cut short when it is long (it may be megabytes).
std::string Quoted(std::string_view text) {
  constexpr std::size_t kShown = 40;
  if (text.size() <= kShown) return "\"" + std::string(text) + "\"";
  return "\"" + std::string(text.substr(0, kShown)) + "...\" (" + std::to_string(text.size()) + " characters)";
}

// Reads exactly `count` finite numbers separated by white space; returns why not, or "" on success. Locale-
// independent (std::from_chars), unlike the strtod and stream reads the XML libraries use.
std::string ReadNumbers(const char* text, int count, double* out) {
  const char* p = text;
  const char* const end = text + std::strlen(text);
  int n = 0;
  while (true) {
    while (p < end && IsSpace(*p)) ++p;
    if (p == end) break;
    const char* token_end = p;
    while (token_end < end && !IsSpace(*token_end)) ++token_end;
    const std::string_view token(p, static_cast<std::size_t>(token_end - p));
    if (n == count) {
      return "holds more than " + std::to_string(count) + (count == 1 ? " number" : " numbers");
    }
    const char* first = p;
    if (*first == '+' && first + 1 < token_end && first[1] != '-') ++first;
    double value = 0.0;
    const std::from_chars_result result = std::from_chars(first, token_end, value);
    if (result.ec != std::errc() || result.ptr != token_end || !std::isfinite(value)) {
      return Quoted(token) + " is not a finite number";
    }
    out[n++] = value;
    p = token_end;
  }
  if (n < count) {
    return "holds " + std::to_string(n) + (n == 1 ? " number" : " numbers") + " where " + std::to_string(count) +
           (count == 1 ? " is" : " are") + " expected";
  }
  return "";
}

// Checks the numeric attributes of one link, joint or material, naming it in every message.
class ElementChecker {
 public:
  ElementChecker(const std::string& source, std::string owner) : source_(source), owner_(std::move(owner)) {}

  [[noreturn]] void Fail(const TiXmlElement& element, const char* attribute, const std::string& why) const {
    const char* value = element.Attribute(attribute);
    throw std::runtime_error(source_ + ": " + owner_ + " (line " + std::to_string(element.Row()) + "): <" +
                             element.Value() + " " + attribute + "=" + Quoted(value == nullptr ? "" : value) +
                             ">: " + why);
  }

  // Reads `count` numbers into `out` when the attribute is present (returns whether it was); refuses anything
  // but exactly `count` finite numbers.
  bool Numbers(const TiXmlElement& element, const char* attribute, int count, double* out,
               const char* expected) const {
    const char* text = element.Attribute(attribute);
    if (text == nullptr) return false;
    const std::string why = ReadNumbers(text, count, out);
    if (!why.empty()) Fail(element, attribute, why + "; give " + expected);
    return true;
  }

  bool Number(const TiXmlElement& element, const char* attribute, double* out, const char* expected) const {
    return Numbers(element, attribute, 1, out, expected);
  }

  // Like Number, and the value must be >= 0 (or > 0 when `strict`).
  void NonNegative(const TiXmlElement& element, const char* attribute, bool strict, const char* expected) const {
    double value = 0.0;
    if (!Number(element, attribute, &value, expected)) return;
    if (strict ? !(value > 0.0) : !(value >= 0.0)) {
      Fail(element, attribute, std::string("must be ") + (strict ? "> 0" : ">= 0") + "; give " + expected);
    }
  }

  void Origin(const TiXmlElement* parent) const {
    const TiXmlElement* origin = parent->FirstChildElement("origin");
    if (origin == nullptr) return;
    double v[3];
    Numbers(*origin, "xyz", 3, v, "three numbers x y z in metres");
    Numbers(*origin, "rpy", 3, v, "three angles roll pitch yaw in radians");
  }

  void Color(const TiXmlElement* material) const {
    const TiXmlElement* color = material == nullptr ? nullptr : material->FirstChildElement("color");
    if (color == nullptr) return;
    double rgba[4];
    Numbers(*color, "rgba", 4, rgba, "four numbers r g b a between 0 and 1");
  }

  void Geometry(const TiXmlElement* shape_parent) const {
    const TiXmlElement* geometry = shape_parent->FirstChildElement("geometry");
    if (geometry == nullptr) return;
    for (const TiXmlElement* shape = geometry->FirstChildElement(); shape != nullptr;
         shape = shape->NextSiblingElement()) {
      const std::string kind = shape->Value();
      if (kind == "box") {
        double size[3];
        if (Numbers(*shape, "size", 3, size, "three side lengths > 0 in metres") &&
            !(std::min({size[0], size[1], size[2]}) > 0.0)) {
          Fail(*shape, "size", "every side must be > 0; give three side lengths > 0 in metres");
        }
      } else if (kind == "sphere") {
        NonNegative(*shape, "radius", true, "a radius > 0 in metres");
      } else if (kind == "cylinder") {
        NonNegative(*shape, "radius", true, "a radius > 0 in metres");
        NonNegative(*shape, "length", false, "a length >= 0 in metres");
      } else if (kind == "mesh") {
        double scale[3];
        Numbers(*shape, "scale", 3, scale, "three scale factors x y z");
      }
    }
  }

  void Link(const TiXmlElement& link) const {
    if (const TiXmlElement* inertial = link.FirstChildElement("inertial")) {
      Origin(inertial);
      if (const TiXmlElement* mass = inertial->FirstChildElement("mass")) {
        NonNegative(*mass, "value", false, "a mass >= 0 in kilograms");
      }
      if (const TiXmlElement* inertia = inertial->FirstChildElement("inertia")) {
        for (const char* name : {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"}) {
          double value = 0.0;
          Number(*inertia, name, &value, "a moment of inertia in kg m^2");
        }
      }
    }
    for (const char* kind : {"visual", "collision"}) {
      for (const TiXmlElement* shape = link.FirstChildElement(kind); shape != nullptr;
           shape = shape->NextSiblingElement(kind)) {
        Origin(shape);
        Geometry(shape);
        Color(shape->FirstChildElement("material"));
      }
    }
  }

  void Joint(const TiXmlElement& joint) const {
    Origin(&joint);
    if (const TiXmlElement* axis = joint.FirstChildElement("axis")) {
      double xyz[3];
      Numbers(*axis, "xyz", 3, xyz, "three numbers x y z (a direction, e.g. \"0 0 1\")");
    }
    if (const TiXmlElement* limit = joint.FirstChildElement("limit")) {
      NonNegative(*limit, "effort", false, "an effort limit >= 0 in N m or N (0 for none)");
      NonNegative(*limit, "velocity", false, "a velocity limit >= 0 in rad/s or m/s (0 for none)");
      double lower = 0.0;
      double upper = 0.0;
      Number(*limit, "lower", &lower, "a lower position limit in rad or m");
      Number(*limit, "upper", &upper, "an upper position limit in rad or m");
      const char* type = joint.Attribute("type");
      const bool bounded = type != nullptr && (std::strcmp(type, "revolute") == 0 || std::strcmp(type, "prismatic") == 0);
      if (bounded && lower > upper) {
        Fail(*limit, "lower",
             "exceeds upper=\"" + FormatShort(upper) + "\"; give lower <= upper (swap them if they are reversed)");
      }
    }
    if (const TiXmlElement* dynamics = joint.FirstChildElement("dynamics")) {
      double value = 0.0;
      Number(*dynamics, "damping", &value, "a damping coefficient");
      Number(*dynamics, "friction", &value, "a friction value");
    }
    if (const TiXmlElement* safety = joint.FirstChildElement("safety_controller")) {
      double value = 0.0;
      for (const char* name : {"soft_lower_limit", "soft_upper_limit", "k_position", "k_velocity"}) {
        Number(*safety, name, &value, "a number");
      }
    }
    if (const TiXmlElement* calibration = joint.FirstChildElement("calibration")) {
      double value = 0.0;
      Number(*calibration, "rising", &value, "a position in rad or m");
      Number(*calibration, "falling", &value, "a position in rad or m");
    }
    if (const TiXmlElement* mimic = joint.FirstChildElement("mimic")) {
      double value = 0.0;
      Number(*mimic, "multiplier", &value, "a number");
      Number(*mimic, "offset", &value, "a number");
    }
  }

 private:
  const std::string& source_;
  std::string owner_;
};

std::string Named(const char* kind, const TiXmlElement& element) {
  const char* name = element.Attribute("name");
  return std::string(kind) + " '" + (name == nullptr ? "?" : name) + "'";
}

int LineAt(const std::string& text, std::size_t position) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(position), '\n'));
}

}  // namespace

void UrdfXmlCheck::Fail(const std::string& what) const { throw std::runtime_error(source_ + ": " + what); }

void UrdfXmlCheck::CheckSizeAndNesting(const std::string& xml) const {
  if (xml.size() > kMaxUrdfBytes) {
    Fail("the text is " + std::to_string(xml.size()) + " bytes, more than the limit of " +
         std::to_string(kMaxUrdfBytes) +
         " (64 MiB, kMaxUrdfBytes); robot descriptions are far smaller, so check that this is the URDF file");
  }
  // Mirrors how TinyXML tells markup apart (comments, CDATA, declarations and other "<!" or "<?" nodes end
  // where TinyXML ends them), so the depth counted here is the depth TinyXML would recurse to.
  const std::size_t n = xml.size();
  int depth = 0;
  std::size_t i = 0;
  while ((i = xml.find('<', i)) != std::string::npos) {
    std::size_t end = std::string::npos;
    if (xml.compare(i, 4, "<!--") == 0) {
      end = xml.find("-->", i + 4);
      if (end != std::string::npos) end += 2;
    } else if (xml.compare(i, 9, "<![CDATA[") == 0) {
      end = xml.find("]]>", i + 9);
      if (end != std::string::npos) end += 2;
    } else if (i + 1 < n && xml[i + 1] == '/') {
      depth = std::max(0, depth - 1);
      end = xml.find('>', i + 2);
    } else if (i + 1 < n && (std::isalpha(static_cast<unsigned char>(xml[i + 1])) || xml[i + 1] == '_' ||
                             static_cast<unsigned char>(xml[i + 1]) >= 0x80)) {
      // A start tag: '>' inside a quoted attribute value does not end it.
      char quote = 0;
      for (end = i + 1; end < n; ++end) {
        const char c = xml[end];
        if (quote != 0) {
          if (c == quote) quote = 0;
        } else if (c == '"' || c == '\'') {
          quote = c;
        } else if (c == '>') {
          break;
        }
      }
      if (end == n) return;  // Unterminated; TinyXML reports it with a position.
      if (xml[end - 1] != '/' && ++depth > kMaxUrdfNestingDepth) {
        Fail("XML elements nest more than " + std::to_string(kMaxUrdfNestingDepth) +
             " levels deep (kMaxUrdfNestingDepth) at line " + std::to_string(LineAt(xml, i)) +
             "; a URDF nests about 5, so this is not a valid robot description");
      }
    } else {
      end = xml.find('>', i + 1);  // "<?...>", "<!DOCTYPE ...>" and other unknown nodes.
    }
    if (end == std::string::npos) return;
    i = end + 1;
  }
}

void UrdfXmlCheck::CheckDocument(const std::string& xml) const {
  if (std::all_of(xml.begin(), xml.end(), IsSpace)) {
    Fail("the text is empty; a URDF file holds a <robot name=...> element");
  }
  TiXmlDocument document;
  document.Parse(xml.c_str());
  if (document.Error()) {
    Fail("malformed XML at line " + std::to_string(document.ErrorRow()) + ", column " +
         std::to_string(document.ErrorCol()) + ": " + document.ErrorDesc());
  }
  const TiXmlElement* robot = document.FirstChildElement("robot");
  if (robot == nullptr) Fail("no <robot> element; a URDF file's root element is <robot name=...>");
  for (const TiXmlElement* material = robot->FirstChildElement("material"); material != nullptr;
       material = material->NextSiblingElement("material")) {
    ElementChecker(source_, Named("material", *material)).Color(material);
  }
  for (const TiXmlElement* link = robot->FirstChildElement("link"); link != nullptr;
       link = link->NextSiblingElement("link")) {
    ElementChecker(source_, Named("link", *link)).Link(*link);
  }
  for (const TiXmlElement* joint = robot->FirstChildElement("joint"); joint != nullptr;
       joint = joint->NextSiblingElement("joint")) {
    ElementChecker(source_, Named("joint", *joint)).Joint(*joint);
  }
}

}  // namespace cairn::multibody::internal
