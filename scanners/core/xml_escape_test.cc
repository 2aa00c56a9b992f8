#include "scanners/core/xml_escape.h"

#include <gtest/gtest.h>

namespace bespoke {
namespace {

TEST(XmlEscape, ReplacesTheFiveMarkupCharactersOnly) {
  EXPECT_EQ(XmlEscape("waist < hip & \"seat\" > 'rise'"),
            "waist &lt; hip &amp; &quot;seat&quot; &gt; &apos;rise&apos;");
  EXPECT_EQ(XmlEscape("tour de taille – 76 cm"), "tour de taille – 76 cm");  // UTF-8 kept
  EXPECT_EQ(XmlEscape(""), "");
  EXPECT_EQ(XmlEscape("&amp;"), "&amp;amp;");  // escaped once more, never skipped
}

}  // namespace
}  // namespace bespoke
