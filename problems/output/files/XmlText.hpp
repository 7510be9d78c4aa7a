// Text for XML and HTML: the VTK collections' attributes and the verification report's page.
#pragma once

#include <string>

namespace beamrotor {

/// text with &, <, > and " escaped, safe inside an element or a double-quoted attribute.
std::string xmlEscape(const std::string& text);

}  // namespace beamrotor
