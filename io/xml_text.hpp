#pragma once

// Text for the XML files the writers make (XDMF, VTK): escaped values and exact numbers.

#include <string>
#include <string_view>

namespace tide::io {

/// Text for an XML attribute value or element content, written between double quotes.
std::string xml_escaped(std::string_view text);

/// The shortest text that reads back as the same double, so a time in XML equals the stored one.
std::string exact_text(double value);

}  // namespace tide::io
