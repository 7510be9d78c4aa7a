#include "tests/problems/output/ChartInspection.hpp"

#include <png.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace beamrotor::test {

namespace fs = std::filesystem;

std::vector<std::string> inkOnImageEdges(const fs::path& png, int band) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, png.c_str())) return {"cannot read " + png.string()};
  image.format = PNG_FORMAT_GRAY;
  std::vector<unsigned char> pixels(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr))
    return {"cannot decode " + png.string()};
  const int width = int(image.width), height = int(image.height);
  constexpr unsigned char kInk = 200;  // grid lines are lighter; text and curves darker
  const auto ink = [&](int x, int y) { return pixels[std::size_t(y) * width + x] < kInk; };
  std::vector<std::string> faults;
  const auto report = [&](const std::string& edge, const std::string& along,
                          const std::vector<int>& at) {
    if (!at.empty())
      faults.push_back(edge + " edge, " + along + " " + std::to_string(at.front()) + " to " +
                       std::to_string(at.back()));
  };
  std::vector<int> left, right, top, bottom;
  for (int y = 0; y < height; ++y)
    for (int k = 0; k < band; ++k) {
      if (ink(k, y)) left.push_back(y);
      if (ink(width - 1 - k, y)) right.push_back(y);
    }
  for (int x = 0; x < width; ++x)
    for (int k = 0; k < band; ++k) {
      if (ink(x, k)) top.push_back(x);
      if (ink(x, height - 1 - k)) bottom.push_back(x);
    }
  report("left", "rows", left);
  report("right", "rows", right);
  report("top", "columns", top);
  report("bottom", "columns", bottom);
  return faults;
}

namespace {

struct TextBox {
  std::string text;
  double left, top, right, bottom;
};

double attribute(const std::string& tag, const std::string& name, double otherwise) {
  const std::size_t at = tag.find(name + "=\"");
  return at == std::string::npos ? otherwise : std::atof(tag.c_str() + at + name.size() + 2);
}

std::string textAttribute(const std::string& tag, const std::string& name) {
  const std::size_t at = tag.find(name + "=\"");
  if (at == std::string::npos) return {};
  const std::size_t from = at + name.size() + 2;
  return tag.substr(from, tag.find('"', from) - from);
}

/// The character data of an element's content, tags dropped.
std::string characters(const std::string& content) {
  std::string out;
  bool inTag = false;
  for (char c : content) {
    if (c == '<') inTag = true;
    else if (c == '>') inTag = false;
    else if (!inTag) out += c;
  }
  const auto first = out.find_first_not_of(" \t\n");
  return first == std::string::npos ? "" : out.substr(first, out.find_last_not_of(" \t\n") + 1 - first);
}

/// Every `<g transform="translate(x,y) [rotate(a)]" ...><text>...</text>` gnuplot writes.
std::vector<TextBox> textBoxes(const std::string& svg) {
  std::vector<TextBox> boxes;
  const std::string opening = "<g transform=\"translate(";
  for (std::size_t at = svg.find(opening); at != std::string::npos;
       at = svg.find(opening, at + 1)) {
    const std::size_t tagEnd = svg.find('>', at);
    const std::string tag = svg.substr(at, tagEnd - at);
    const std::size_t textStart = svg.find_first_not_of(" \t\n", tagEnd + 1);
    if (svg.compare(textStart, 6, "<text>") != 0) continue;
    const std::string text = characters(svg.substr(textStart, svg.find("</text>", textStart) - textStart));
    if (text.empty()) continue;
    char* end = nullptr;
    const double x = std::strtod(tag.c_str() + opening.size(), &end);
    const double y = std::strtod(end + 1, nullptr);
    const std::size_t rotate = tag.find("rotate(");
    const double angle = rotate == std::string::npos ? 0 : std::atof(tag.c_str() + rotate + 7);
    const double em = attribute(tag, "font-size", 12);
    // Characters, not bytes (UTF-8 continuation bytes do not count).
    const auto count = std::count_if(text.begin(), text.end(), [](char c) {
      return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    });
    const double length = 0.5 * em * double(count), ascent = 0.6 * em;
    const std::string anchor = textAttribute(tag, "text-anchor");
    const double from = anchor == "end" ? -length : anchor == "middle" ? -length / 2 : 0;
    // Along the text [from, from + length], across it [-ascent, 0]; gnuplot turns text by
    // -90 or 270 degrees (reading upwards) and leaves the rest level.
    if (std::abs(std::abs(angle) - 90) < 1 || std::abs(angle - 270) < 1)
      boxes.push_back({text, x - ascent, y - from - length, x, y - from});
    else
      boxes.push_back({text, x + from, y - ascent, x + from + length, y});
  }
  return boxes;
}

/// A number whose decimal fraction ends in three or more zeros ("1000.0000000", "2.5000").
bool paddedNumber(const std::string& text) {
  std::size_t i = text[0] == '-' ? 1 : 0;
  const std::size_t digits = i;
  while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
  if (i == digits || i >= text.size() || text[i] != '.') return false;
  const std::size_t point = i++;
  while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
  return i == text.size() && i - point > 3 && text.compare(i - 3, 3, "000") == 0;
}

}  // namespace

std::vector<std::string> textFaults(const fs::path& svgFile) {
  std::ifstream in(svgFile);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string svg = buffer.str();
  std::vector<std::string> faults;
  const std::size_t viewBox = svg.find("viewBox=\"0 0 ");
  if (viewBox == std::string::npos) return {"no viewBox in " + svgFile.string()};
  char* end = nullptr;
  const double width = std::strtod(svg.c_str() + viewBox + 13, &end);
  const double height = std::strtod(end, nullptr);
  const std::vector<TextBox> boxes = textBoxes(svg);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const TextBox& a = boxes[i];
    if (paddedNumber(a.text)) faults.push_back("'" + a.text + "' is padded with zeros");
    if (a.left < 0 || a.top < 0 || a.right > width || a.bottom > height)
      faults.push_back("'" + a.text + "' reaches outside the canvas");
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      const TextBox& b = boxes[j];
      constexpr double kSlack = 1;  // px: boxes that merely touch are fine
      if (std::min(a.right, b.right) - std::max(a.left, b.left) > kSlack &&
          std::min(a.bottom, b.bottom) - std::max(a.top, b.top) > kSlack)
        faults.push_back("'" + a.text + "' and '" + b.text + "' overlap");
    }
  }
  return faults;
}

}  // namespace beamrotor::test
