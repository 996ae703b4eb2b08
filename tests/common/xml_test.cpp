// Text in XML element content (common/xml.h): the characters that start markup or an entity
// are escaped, and unescaping gives the text back.

#include "common/xml.h"

#include <gtest/gtest.h>

#include <string>

namespace systole {
namespace {

std::string unescape(const std::string& xml) {
  std::string out;
  for (std::size_t i = 0; i < xml.size();) {
    if (xml.compare(i, 4, "&lt;") == 0) out += '<', i += 4;
    else if (xml.compare(i, 4, "&gt;") == 0) out += '>', i += 4;
    else if (xml.compare(i, 5, "&amp;") == 0) out += '&', i += 5;
    else out += xml[i++];
  }
  return out;
}

TEST(Xml, EscapesMarkupAndEntities) {
  EXPECT_EQ(xml_text("a<b>&c"), "a&lt;b&gt;&amp;c");
  EXPECT_EQ(xml_text("&amp;"), "&amp;amp;");  // An entity in the text stays text.
  EXPECT_EQ(xml_text("plain \"quoted\" 'text' é"), "plain \"quoted\" 'text' é");
  EXPECT_EQ(xml_text(""), "");
}

TEST(Xml, EscapedTextHasNoMarkupAndUnescapesToItself) {
  const std::string texts[] = {"<svg onload=alert(1)>", "&&&<<<>>>", "ΔP = 120 mmHg & rising", "</text><text>"};
  for (const std::string& t : texts) {
    const std::string x = xml_text(t);
    EXPECT_EQ(x.find('<'), std::string::npos) << t;
    EXPECT_EQ(x.find('>'), std::string::npos) << t;
    EXPECT_EQ(unescape(x), t);
  }
}

}  // namespace
}  // namespace systole
