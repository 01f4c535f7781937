// mobb scenario import as a user meets it: a SteerSuite test case (written here in SteerSuite's schema)
// becomes a scenario file that `mobb crowd --scenario` runs; what mobb cannot do goes to stderr; bad input
// is one error line with nothing on stdout and no file written; a test case with no agent is a map.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "files.h"
#include "mobb/crowd/scenario/scenario.h"
#include "run.h"

namespace mobb {
namespace {

using test::Result;
using test::temp_file;

const std::string kGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json";

// Two agents that swap sides past a pillar, and one that starts against it (moved clear of it, with a note).
const char* kCase = R"(<SteerBenchTestCase xmlns="http://www.magix.ucla.edu/steerbench">
  <header>
    <version>1.0</version>
    <name>swap</name>
    <worldBounds> <xmin>-8</xmin> <xmax>8</xmax> <ymin>0</ymin> <ymax>0</ymax> <zmin>-6</zmin> <zmax>6</zmax> </worldBounds>
  </header>
  <obstacle> <xmin>-0.5</xmin> <xmax>0.5</xmax> <ymin>0</ymin> <ymax>1</ymax> <zmin>-0.5</zmin> <zmax>0.5</zmax> </obstacle>
  <agent>
    <initialConditions> <radius>0.5</radius> <position> <x>-5</x> <y>0</y> <z>0</z> </position>
      <direction> <x>1</x> <y>0</y> <z>0</z> </direction> <speed>0</speed> </initialConditions>
    <goalSequence>
      <seekStaticTarget> <targetLocation> <x>5</x> <y>0</y> <z>0</z> </targetLocation>
        <desiredSpeed>1.3</desiredSpeed> <timeDuration>100</timeDuration> </seekStaticTarget>
    </goalSequence>
  </agent>
  <agent>
    <initialConditions> <radius>0.5</radius> <position> <x>5</x> <y>0</y> <z>1.5</z> </position>
      <direction> <x>-1</x> <y>0</y> <z>0</z> </direction> <speed>0</speed> </initialConditions>
    <goalSequence>
      <seekStaticTarget> <targetLocation> <x>-5</x> <y>0</y> <z>1.5</z> </targetLocation>
        <desiredSpeed>1.3</desiredSpeed> <timeDuration>100</timeDuration> </seekStaticTarget>
    </goalSequence>
  </agent>
  <agent>
    <initialConditions> <radius>0.5</radius> <position> <x>0</x> <y>0</y> <z>-1</z> </position>
      <direction> <x>0</x> <y>0</y> <z>-1</z> </direction> <speed>0</speed> </initialConditions>
    <goalSequence>
      <seekStaticTarget> <targetLocation> <x>0</x> <y>0</y> <z>-5</z> </targetLocation>
        <desiredSpeed>1.3</desiredSpeed> <timeDuration>100</timeDuration> </seekStaticTarget>
    </goalSequence>
  </agent>
</SteerBenchTestCase>
)";

std::string write(const std::string& name, const std::string& text) {
    const std::string file = temp_file(name);
    std::ofstream(file) << text;
    return file;
}

TEST(ScenarioCli, ImportThenCrowdRunsIt) {
    const std::string xml = write("swap.xml", kCase), json = temp_file("swap.json");
    const Result r =
        test::run_mobb("scenario import " + xml + " --out " + json + " --seed 2 --time-limit 4 --graph " + kGraph);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, json + ": scenario swap, 3 agents, 1 obstacle, 16 x 12 m, time limit 4 s\n");
    EXPECT_NE(r.err.find("note: " + xml +
                         ":24: agent: starts 0.5 m from a wall or an obstacle; mobb's agents need 0.58 m to stand: "
                         "moved 0.09 m to (0, -1.09), the nearest place with room\n"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("note: " + xml + ": speeds of 0 to 1.3 m/s ignored"), std::string::npos) << r.err;
    const crowd::Scenario s = crowd::load_scenario(json);
    ASSERT_EQ(s.agents.size(), 3u);
    EXPECT_EQ(s.agents[2].start.y, -1.09);
    EXPECT_NE(r.err.find(":24: agent: starts 0.59 m from a wall or an obstacle: room to stand, not to turn round"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(s.time_limit, 4);
    const Result run = test::run_mobb("crowd --quiet --graph " + kGraph + " --scenario " + json);
    ASSERT_EQ(run.code, 0) << run.err;
    EXPECT_EQ(run.out.rfind("scenario swap: 3 agents, 16 x 12 m, 4 s", 0), 0u) << run.out;
    std::remove(xml.c_str());
    std::remove(json.c_str());
}

// The default graph is found as `mobb crowd` finds it (from the source tree this was built from).
TEST(ScenarioCli, DefaultGraph) {
    const std::string xml = write("swap2.xml", kCase), json = temp_file("swap2.json");
    const Result r = test::run_mobb("scenario import " + xml + " --out " + json);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(crowd::load_scenario(json).agents.size(), 3u);
    std::remove(xml.c_str());
    std::remove(json.c_str());
}

TEST(ScenarioCli, BadInputIsOneLineAndNoFile) {
    const std::string xml =
        write("broken.xml", std::string(kCase).replace(std::string(kCase).find("<x>5</x>"), 8, "<x>five</x>"));
    const std::string json = temp_file("broken.json");
    std::remove(json.c_str());
    Result r = test::run_mobb("scenario import " + xml + " --out " + json + " --graph " + kGraph);
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "error: " + xml + ":12: x: expected a number, got \"five\"\n");
    EXPECT_FALSE(std::ifstream(json).good());

    const std::string text = write("text.xml", "not xml at all <\n");
    r = test::run_mobb("scenario import " + text + " --out " + json + " --graph " + kGraph);
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("error: " + text + ":1: XML: ", 0), 0u) << r.err;
    EXPECT_FALSE(std::ifstream(json).good());

    r = test::run_mobb("scenario import " + xml);  // --out is required: a usage error
    EXPECT_EQ(r.code, 2);
    std::remove(xml.c_str());
    std::remove(text.c_str());
}

// Every agent left out (here: each starts outside SteerSuite's own ground, which the world becomes): the
// notes say why, and no file is written that `mobb crowd` would refuse.
TEST(ScenarioCli, NoAgentLeftWritesNothing) {
    std::string text = kCase;
    for (const char* from :
         {"<x>-5</x> <y>0</y> <z>0</z>", "<x>5</x> <y>0</y> <z>1.5</z>", "<x>0</x> <y>0</y> <z>-1</z>"})
        text.replace(text.find(from), std::string(from).size(), "<x>150</x> <y>0</y> <z>0</z>");
    const std::string xml = write("nobody.xml", text), json = temp_file("nobody.json");
    std::remove(json.c_str());
    const Result r = test::run_mobb("scenario import " + xml + " --out " + json + " --graph " + kGraph);
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find("note: " + xml +
                         ":8: agent: starts outside the world, and no place within 1 m has room: left "
                         "out\n"),
              std::string::npos)
        << r.err;
    const std::string last = "error: " + xml + ": no agent mobb can run is left (see the notes): nothing written\n";
    EXPECT_EQ(r.err.substr(r.err.size() - std::min(r.err.size(), last.size())), last) << r.err;
    EXPECT_FALSE(std::ifstream(json).good());
    std::remove(xml.c_str());
}

// A test case with no agent (SteerSuite's BigGameHunters is a map of walls) is written as its world alone;
// `mobb crowd` then says in one line that it has nothing to run.
TEST(ScenarioCli, MapWithoutAgents) {
    std::string text = kCase;
    text.erase(text.find("  <agent>"), text.rfind("</agent>") + 9 - text.find("  <agent>"));
    const std::string xml = write("map.xml", text), json = temp_file("map.json");
    const Result r = test::run_mobb("scenario import " + xml + " --out " + json + " --graph " + kGraph);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, json + ": scenario swap, 0 agents, 1 obstacle, 16 x 12 m, time limit 20 s\n");
    EXPECT_NE(r.err.find("note: " + xml + ": the test case has no agent: the scenario is its world alone, a map"),
              std::string::npos)
        << r.err;
    const crowd::Scenario s = crowd::load_scenario(json);
    EXPECT_TRUE(s.agents.empty());
    EXPECT_EQ(s.world.obstacles.size(), 1u);
    const Result run = test::run_mobb("crowd --quiet --graph " + kGraph + " --scenario " + json);
    EXPECT_EQ(run.code, 1);
    EXPECT_EQ(run.out, "");
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_EQ(run.err.rfind("error: " + json + ": ", 0), 0u) << run.err;
    std::remove(xml.c_str());
    std::remove(json.c_str());
}

}  // namespace
}  // namespace mobb
