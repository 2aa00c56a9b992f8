// The reference table (REF.csv) and name maps: every row-level problem is
// left out with its reason, every whole-file problem is an InputError naming
// the file; the ready maps agree with the catalogue's names for other tools.
#include "eval/accuracy/reference_table.h"

#include <gtest/gtest.h>

#include <fstream>

#include "eval/accuracy/name_map.h"
#include "scanners/core/errors.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

fs::path Write(const TempDir& dir, const std::string& name, const std::string& text) {
  const fs::path file = dir / name;
  std::ofstream(file) << text;
  return file;
}

ReferenceTable Read(const fs::path& file, const NameMap* names = nullptr,
                    const std::string& method = "") {
  ReferenceTableOptions options;
  options.names = names;
  options.method = method;
  return ReadReferenceTable(options, file, Catalogue::Builtin());
}

// The reason given for the row on `line`, or "" when it was compared.
std::string ReasonFor(const ReferenceTable& table, int line) {
  for (const NotCompared& n : table.not_compared) {
    if (n.where == "REF.csv line " + std::to_string(line)) return n.reason;
  }
  return "";
}

TEST(ReferenceTable, ReadsValuesAndLeavesOutBadRowsWithTheReason) {
  TempDir dir;
  const fs::path file = Write(dir, "REF.csv",
                              "# tape measurements\n"
                              "Subject,Measurement,Value_mm,Unit\n"  // line 2
                              "anna,waist_girth,712.5,mm\n"          // 3 ok
                              "anna,stature,1650,\n"                 // 4 ok (empty unit)
                              "anna,waist_girth,712.5,mm\n"          // 5 duplicate, same value
                              "ben,hip_girth,99x,mm\n"               // 6 not a number
                              "ben,hip_girth,-3,mm\n"                // 7 not positive
                              "ben,stature,178,cm\n"                 // 8 unit cm
                              "ben,shoe_size,42,mm\n"                // 9 unknown name
                              ",stature,1700,mm\n"                   // 10 no subject
                              "cleo,stature,1600,mm\n"               // 11 conflicts with 12
                              "cleo,stature,1610,mm\n"               // 12
                              "cleo,\"neck_girth\",\"350.25\",\"mm\"\n");  // 13 ok (quoted)
  const ReferenceTable t = Read(file);
  ASSERT_EQ(t.values.size(), 3u);
  EXPECT_EQ(t.values[0].subject, "anna");
  EXPECT_EQ(t.values[0].measurement, "waist_girth");
  EXPECT_DOUBLE_EQ(t.values[0].value_mm, 712.5);
  EXPECT_EQ(t.values[0].line, 3);
  EXPECT_DOUBLE_EQ(t.values[2].value_mm, 350.25);
  EXPECT_EQ(t.subjects, (std::vector<std::string>{"anna", "cleo"}));
  EXPECT_EQ(ReasonFor(t, 3), "");
  EXPECT_NE(ReasonFor(t, 5).find("duplicate of line 3"), std::string::npos);
  EXPECT_NE(ReasonFor(t, 6).find("'99x' is not a number"), std::string::npos);
  EXPECT_NE(ReasonFor(t, 7).find("not a positive length"), std::string::npos);
  EXPECT_NE(ReasonFor(t, 8).find("unit 'cm'"), std::string::npos);
  EXPECT_NE(ReasonFor(t, 9).find("unknown measurement"), std::string::npos);
  EXPECT_NE(ReasonFor(t, 10).find("no subject"), std::string::npos);
  EXPECT_NE(ReasonFor(t, 11).find("conflicts"), std::string::npos);
  EXPECT_NE(ReasonFor(t, 12).find("conflicts with line 11"), std::string::npos);
  EXPECT_EQ(t.not_compared.size(), 8u);
  // Row-level reasons name the subject and the measurement as written.
  for (const NotCompared& n : t.not_compared) {
    if (n.where == "REF.csv line 9") {
      EXPECT_EQ(n.subject, "ben");
      EXPECT_EQ(n.measurement, "shoe_size");
    }
  }
}

TEST(ReferenceTable, WholeFileProblemsAreErrorsNamingTheFile) {
  TempDir dir;
  const auto message = [&](const std::string& text, const std::string& method = "") {
    const fs::path file = Write(dir, "REF.csv", text);
    try {
      Read(file, nullptr, method);
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("REF.csv"), std::string::npos) << what;
      return what;
    }
    return std::string("no error");
  };
  EXPECT_NE(message("").find("empty"), std::string::npos);
  EXPECT_NE(message("subject,measurement,value_cm\na,stature,170\n").find("'value_cm' is in cm"),
            std::string::npos);
  EXPECT_NE(message("subject,measurement,value\na,stature,1700\n").find("does not say its unit"),
            std::string::npos);
  EXPECT_NE(message("subject,value_mm\na,1700\n").find("'measurement' is missing"),
            std::string::npos);
  EXPECT_NE(message("subject,measurement,value_mm\na,\"stature,1700\n").find("unterminated"),
            std::string::npos);
  const std::string two_methods =
      "subject,measurement,value_mm,method\na,stature,1700,tape\na,stature,1702,vitus\n";
  EXPECT_NE(message(two_methods).find("several methods (tape, vitus)"), std::string::npos);
  EXPECT_NE(message(two_methods, "laser").find("no row has the method 'laser'"), std::string::npos);
  EXPECT_NE(
      message("subject,measurement,value_mm\na,stature,1700\n", "tape").find("no method column"),
      std::string::npos);
  EXPECT_THROW(Read(dir / "missing.csv"), InputError);
}

TEST(ReferenceTable, ChosenMethodLeavesTheOthersOut) {
  TempDir dir;
  const fs::path file = Write(dir, "REF.csv",
                              "subject,measurement,value_mm,method\n"
                              "a,stature,1700,tape\n"
                              "a,stature,1702,vitus\n"
                              "a,waist_girth,800,\n");  // empty method: the compared one
  const ReferenceTable t = Read(file, nullptr, "tape");
  EXPECT_EQ(t.method, "tape");
  ASSERT_EQ(t.values.size(), 2u);  // no conflict: the vitus row is not compared at all
  EXPECT_DOUBLE_EQ(t.values[0].value_mm, 1700);
  EXPECT_EQ(t.values[1].method, "tape");
  EXPECT_NE(ReasonFor(t, 3).find("method 'vitus'"), std::string::npos);
}

TEST(NameMap, TheirNamesAreMappedWithTheirNotes) {
  TempDir dir;
  const NameMap map = LoadNameMap("freesewing", Catalogue::Builtin());
  const fs::path file = Write(dir, "REF.csv",
                              "subject,measurement,value_mm\n"
                              "a,biceps,310\n"    // line 2: mapped, with a note
                              "a,Chest,930\n"     // 3: ignoring case
                              "a,head,560\n"      // 4: no counterpart
                              "a,stature,1700\n"  // 5: catalogue names still work
                              "a,biceps,310\n");  // 6: a duplicate after mapping
  const ReferenceTable t = Read(file, &map);
  ASSERT_EQ(t.values.size(), 3u);
  EXPECT_EQ(t.values[0].measurement, "upper_arm_girth");
  EXPECT_EQ(t.values[1].measurement, "bust_girth");
  EXPECT_EQ(t.values[2].measurement, "stature");
  EXPECT_NE(ReasonFor(t, 4).find("no Bespoke counterpart"), std::string::npos);
  EXPECT_NE(ReasonFor(t, 6).find("duplicate of line 2"), std::string::npos);
  ASSERT_EQ(t.mapped_names.size(), 3u);
  EXPECT_EQ(t.mapped_names[0].their_name, "biceps");
  EXPECT_EQ(t.mapped_names[0].rows, 2);
  EXPECT_FALSE(t.mapped_names[0].note.empty());
  EXPECT_TRUE(t.mapped_names[1].note.empty());  // chest: the definitions agree
}

// Every name the catalogue gives another tool (what our exports write) is in
// that tool's ready map, pointing at the same measurement unless a note says
// why it does not.
TEST(NameMap, ReadyMapsAgreeWithTheCatalogue) {
  const Catalogue& catalogue = Catalogue::Builtin();
  const NameMap valentina = LoadNameMap("valentina", catalogue);
  const NameMap freesewing = LoadNameMap("freesewing", catalogue);
  EXPECT_GT(valentina.by_key.size(), 45u);
  EXPECT_EQ(freesewing.by_key.size(), 38u);  // FreeSewing's whole list
  int checked = 0;
  for (const MeasurementDef& m : catalogue.measurements()) {
    for (const auto& [their, map] :
         {std::make_pair(m.valentina, &valentina), std::make_pair(m.freesewing, &freesewing)}) {
      if (their.empty()) continue;
      const std::optional<NameMapEntry> entry = map->Find(their);
      ASSERT_TRUE(entry) << map->source << " lacks " << their;
      if (entry->measurement != m.name) {
        EXPECT_FALSE(entry->note.empty()) << their << " -> " << entry->measurement;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 60);
}

TEST(NameMap, BadMapsAreErrors) {
  TempDir dir;
  const Catalogue& catalogue = Catalogue::Builtin();
  const auto message = [&](const std::string& text) {
    try {
      LoadNameMap(Write(dir, "map.csv", text).string(), catalogue);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("name,ours\n").find("their_name and our_name"), std::string::npos);
  EXPECT_NE(message("their_name,our_name\nx,no_such\n").find("'no_such' is not a catalogue"),
            std::string::npos);
  EXPECT_NE(message("their_name,our_name\nX,stature\nx,stature\n").find("mapped again"),
            std::string::npos);
  EXPECT_THROW(LoadNameMap("seamly", catalogue), InputError);
  const NameMap own = LoadNameMap(
      Write(dir, "map.csv", "their_name,our_name,note\nHeight,stature,\n").string(), catalogue);
  ASSERT_TRUE(own.Find("height"));
  EXPECT_EQ(own.Find("HEIGHT")->measurement, "stature");
}

}  // namespace
}  // namespace bespoke
