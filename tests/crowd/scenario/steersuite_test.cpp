// SteerSuite test cases imported as scenarios, on small files written here in SteerSuite's schema: the
// mapping of coordinates and obstacles, random agent and obstacle regions (counts, room, determinism),
// every note, every error with its line, and the result run by the crowd.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "files.h"
#include "mobb/core/angle.h"
#include "mobb/crowd/collision/narrow_phase.h"
#include "mobb/crowd/scenario/steersuite.h"
#include "mobb/crowd/sim/crowd.h"

namespace mobb::crowd {
namespace {

const std::string kGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json";
const AgentRoom kRoom;  // the documented defaults: these tests do not depend on the graph

// A test case file: the header (world x in [-10, 10], z in [-20, 20] unless told) and `items`.
std::string write_case(const std::string& name, const std::string& items,
                       const std::string& bounds = "-10 10 0 0 -20 20") {
    std::istringstream b(bounds);
    std::string v[6];
    for (auto& x : v) b >> x;
    const std::string text =
        "<!-- a test case written for mobb's tests -->\n"
        "<SteerBenchTestCase xmlns=\"http://www.magix.ucla.edu/steerbench\">\n"
        "  <header>\n"
        "    <version>1.0</version>\n"
        "    <name>" +
        name +
        "</name>\n"
        "    <worldBounds> <xmin>" +
        v[0] + "</xmin> <xmax>" + v[1] + "</xmax> <ymin>" + v[2] + "</ymin> <ymax>" + v[3] + "</ymax> <zmin>" + v[4] +
        "</zmin> <zmax>" + v[5] +
        "</zmax> </worldBounds>\n"
        "  </header>\n" +
        items + "</SteerBenchTestCase>\n";
    const std::string file = test::temp_file(name + ".xml");
    std::ofstream(file) << text;
    return file;
}

std::string xyz(double x, double y, double z) {
    std::ostringstream s;
    s << "<x>" << x << "</x> <y>" << y << "</y> <z>" << z << "</z>";
    return s.str();
}

std::string seek(double x, double z, double speed = 1.3) {
    std::ostringstream s;
    s << "      <seekStaticTarget> <targetLocation> " << xyz(x, 0, z) << " </targetLocation> <desiredSpeed>" << speed
      << "</desiredSpeed> <timeDuration>1000</timeDuration> </seekStaticTarget>\n";
    return s.str();
}

// One <agent> on 6 lines: at (x, z) facing `direction`, with the given goals.
std::string agent(double x, double z, const std::string& goals, const std::string& direction = xyz(1, 0, 0)) {
    return "  <agent>\n    <initialConditions> <radius>0.5</radius> <position> " + xyz(x, 0, z) +
           " </position>\n      <direction> " + direction + " </direction> <speed>0</speed> </initialConditions>\n" +
           "    <goalSequence>\n" + goals + "    </goalSequence>\n  </agent>\n";
}

// One <obstacle> on one line.
std::string obstacle(double x0, double x1, double z0, double z1) {
    std::ostringstream s;
    s << "  <obstacle> <xmin>" << x0 << "</xmin> <xmax>" << x1 << "</xmax> <ymin>0</ymin> <ymax>1</ymax> <zmin>" << z0
      << "</zmin> <zmax>" << z1 << "</zmax> </obstacle>\n";
    return s.str();
}

std::string region(int n, double x0, double x1, double z0, double z1, const std::string& goals,
                   const std::string& direction = "<random>true</random>") {
    std::ostringstream s;
    s << "  <agentRegion>\n    <numAgents>" << n << "</numAgents>\n    <regionBounds> <xmin>" << x0 << "</xmin> <xmax>"
      << x1 << "</xmax> <ymin>0</ymin> <ymax>0</ymax> <zmin>" << z0 << "</zmin> <zmax>" << z1
      << "</zmax> </regionBounds>\n    <initialConditions> <direction> " << direction
      << " </direction> <radius>0.5</radius> <speed>0</speed> </initialConditions>\n    <goalSequence>\n"
      << goals << "    </goalSequence>\n  </agentRegion>\n";
    return s.str();
}

ImportedScenario import(const std::string& file, std::uint64_t seed = 1) {
    ImportOptions o;
    o.seed = seed;
    return import_steersuite(file, kRoom, o);
}

// The notes that contain `text`.
std::vector<std::string> notes_with(const ImportedScenario& s, const std::string& text) {
    std::vector<std::string> out;
    for (const std::string& n : s.notes)
        if (n.find(text) != std::string::npos) out.push_back(n);
    return out;
}

std::string error_of(const std::string& file) {
    try {
        import(file);
    } catch (const SteerSuiteError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(SteerSuite, MapsGroundXZToXY) {
    const std::string file =
        write_case("mapping", agent(2, -3, seek(5, 4), xyz(0, 0, 1)) + obstacle(3, 4, 5, 7) + obstacle(-8, -6, -1, 1));
    const ImportedScenario s = import(file);
    EXPECT_EQ(s.scenario.name, "mapping");
    EXPECT_NE(s.scenario.source.find("mapping.xml"), std::string::npos);
    const World& w = s.scenario.world;
    EXPECT_EQ(std::vector<double>({w.x0, w.y0, w.x1, w.y1}), std::vector<double>({-10, -20, 10, 20}));
    EXPECT_TRUE(w.walls);
    ASSERT_EQ(w.obstacles.size(), 2u);
    EXPECT_EQ(w.obstacles[0].vertices, Polygon::rectangle(3, 5, 4, 7).vertices);
    EXPECT_EQ(w.obstacles[1].vertices, Polygon::rectangle(-8, -1, -6, 1).vertices);
    ASSERT_EQ(s.scenario.agents.size(), 1u);
    const AgentSpec& a = s.scenario.agents[0];
    EXPECT_EQ(a.start.x, 2.0);
    EXPECT_EQ(a.start.y, -3.0);
    EXPECT_NEAR(degrees(a.start.theta), 90, 1e-12);  // SteerSuite's +z is mobb's +y
    EXPECT_EQ(a.goals, (std::vector<std::array<double, 2>>{{5, 4}}));
    EXPECT_EQ(a.at_goal, AtGoal::Leave);  // SteerSuite's agents leave at their goal
    EXPECT_GT(s.scenario.time_limit, 0);
    std::remove(file.c_str());
}

TEST(SteerSuite, NoDirectionFacesTheGoal) {
    const std::string file = write_case("facing", agent(0, 0, seek(-5, -5), xyz(0, 0, 0)));
    const ImportedScenario s = import(file);
    ASSERT_EQ(s.scenario.agents.size(), 1u);
    EXPECT_NEAR(degrees(s.scenario.agents[0].start.theta), -135, 1e-12);
    std::remove(file.c_str());
}

// What the importer writes is what load_scenario reads (the format of scenario.h), and it runs.
TEST(SteerSuite, WrittenScenarioLoadsAndRuns) {
    const std::string file = write_case(
        "runs", agent(-5, 0, seek(5, 0)) + agent(5, 1.5, seek(-5, 1.5), xyz(-1, 0, 0)) + obstacle(-1, 1, 8, 9));
    ImportOptions o;
    o.time_limit = 2.0;
    const ImportedScenario s = import_steersuite(file, kRoom, o);
    EXPECT_EQ(s.scenario.time_limit, 2.0);
    const std::string json_file = test::temp_file("runs.json");
    std::ofstream(json_file) << scenario_json(s.scenario);
    const Scenario back = load_scenario(json_file);
    EXPECT_EQ(back.name, s.scenario.name);
    EXPECT_EQ(back.description, s.scenario.description);
    EXPECT_EQ(back.source, s.scenario.source);
    EXPECT_EQ(back.time_limit, 2.0);
    ASSERT_EQ(back.world.obstacles.size(), 1u);
    EXPECT_EQ(back.world.obstacles[0].vertices, s.scenario.world.obstacles[0].vertices);
    ASSERT_EQ(back.agents.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_EQ(back.agents[k].start.x, s.scenario.agents[k].start.x);
        EXPECT_EQ(back.agents[k].start.y, s.scenario.agents[k].start.y);
        EXPECT_NEAR(back.agents[k].start.theta, s.scenario.agents[k].start.theta, 1e-6);
        EXPECT_EQ(back.agents[k].goals, s.scenario.agents[k].goals);
        EXPECT_EQ(back.agents[k].at_goal, s.scenario.agents[k].at_goal);
    }
    const MotionGraph g = load_graph(kGraph);
    const CrowdRun run = run_crowd(g, NarrowPhase::sweep(g), scenario_options(back));
    EXPECT_EQ(run.record.tracks.size(), 2u);
    std::remove(file.c_str());
    std::remove(json_file.c_str());
}

// The writer keeps polygons that are not Polygon::rectangle's, thin walls among them.
TEST(SteerSuite, ScenarioJsonKeepsPolygonsAndThinWalls) {
    Scenario s;
    s.name = "shapes";
    s.world = {0, 0, 10, 10, false, {}};
    s.world.obstacles.push_back({{{1, 1}, {3, 1}, {2, 3}}});
    s.world.obstacles.push_back({{{5, 1}, {5, 4}}});
    s.world.obstacles.push_back(Polygon::rectangle(6, 6, 7, 8));
    AgentSpec a;
    a.start = {1, 8, radians(30), 0};
    a.start_time = 1.5;
    a.goals = {{9, 9}};
    s.agents.push_back(a);
    const nlohmann::json j = nlohmann::json::parse(scenario_json(s));
    EXPECT_EQ(j["obstacles"][0]["polygon"].size(), 3u);
    EXPECT_EQ(j["obstacles"][1]["polygon"].size(), 2u);
    EXPECT_EQ(j["obstacles"][2]["rectangle"], nlohmann::json::array({6, 6, 7, 8}));
    EXPECT_EQ(j["walls"], false);
    const Scenario back = parse_scenario(j, "shapes");
    EXPECT_EQ(back.world.obstacles[0].vertices, s.world.obstacles[0].vertices);
    EXPECT_EQ(back.world.obstacles[1].vertices, s.world.obstacles[1].vertices);
    EXPECT_EQ(back.agents[0].start_time, 1.5);
    EXPECT_NEAR(degrees(back.agents[0].start.theta), 30, 1e-9);
}

TEST(SteerSuite, AgentRegionPlacesItsCountApartAndInside) {
    const std::string file = write_case("region", region(40, -8, 8, -15, 0, seek(0, 15)) + obstacle(-2, 2, -8, -6));
    const ImportedScenario s = import(file, 7);
    const auto& agents = s.scenario.agents;
    ASSERT_EQ(agents.size(), 40u);
    const Polygon block = Polygon::rectangle(-2, -8, 2, -6);
    for (std::size_t a = 0; a < agents.size(); ++a) {
        const Placement& p = agents[a].start;
        EXPECT_TRUE(p.x >= -8 && p.x <= 8 && p.y >= -15 && p.y <= 0) << a;
        EXPECT_FALSE(disk_overlaps(block, p.x, p.y, kRoom.wall_clearance)) << a;
        EXPECT_GE(p.x, -10 + kRoom.wall_clearance);
        EXPECT_LE(p.x, 10 - kRoom.wall_clearance);
        for (std::size_t b = 0; b < a; ++b)
            EXPECT_GE(std::hypot(p.x - agents[b].start.x, p.y - agents[b].start.y), 2 * kRoom.hold_radius);
        EXPECT_EQ(agents[a].goals.back(), (std::array<double, 2>{0, 15}));
    }
    EXPECT_EQ(notes_with(s, "seed 7").size(), 1u);
    std::remove(file.c_str());
}

TEST(SteerSuite, SameSeedSameScenario) {
    const std::string file =
        write_case("seeded", region(25, -9, 9, -19, 19,
                                    seek(0, 0) + "<seekStaticTarget> <targetLocation> "
                                                 "<random>true</random> </targetLocation> "
                                                 "<desiredSpeed>1</desiredSpeed> "
                                                 "<timeDuration>50</timeDuration> "
                                                 "</seekStaticTarget>\n") +
                                 "  <obstacleRegion> <numObstacles>6</numObstacles> <regionBounds> <xmin>-9</xmin> "
                                 "<xmax>9</xmax> <ymin>0</ymin> <ymax>1</ymax> <zmin>-19</zmin> <zmax>19</zmax> "
                                 "</regionBounds> <obstacleSize>1</obstacleSize> <obstacleHeight>1</obstacleHeight> "
                                 "</obstacleRegion>\n");
    const std::string a = scenario_json(import(file, 3).scenario), b = scenario_json(import(file, 3).scenario);
    const std::string c = scenario_json(import(file, 4).scenario);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
    const Scenario s = import(file, 3).scenario;
    EXPECT_EQ(s.agents.size(), 25u);
    ASSERT_EQ(s.world.obstacles.size(), 6u);
    for (const Polygon& p : s.world.obstacles) {
        const auto b2 = bounds(p);
        EXPECT_NEAR(b2[2] - b2[0], 1, 1e-9);
        EXPECT_NEAR(b2[3] - b2[1], 1, 1e-9);
        EXPECT_TRUE(b2[0] >= -9 && b2[2] <= 9 && b2[1] >= -19 && b2[3] <= 19);
    }
    std::remove(file.c_str());
}

// A region too small for its agents: those that fit, and a note on its line.
TEST(SteerSuite, RegionWithoutRoomKeepsThoseThatFit) {
    const std::string items = region(50, -3, 3, -3, 3, seek(0, 15));
    const std::string file = write_case("crowded", items);
    const ImportedScenario s = import(file);
    EXPECT_GT(s.scenario.agents.size(), 5u);
    EXPECT_LT(s.scenario.agents.size(), 50u);
    const auto n = notes_with(s, "of its 50 agents");
    ASSERT_EQ(n.size(), 1u);
    EXPECT_EQ(n[0].rfind(file + ":8: agentRegion: room for " + std::to_string(s.scenario.agents.size()), 0), 0u)
        << n[0];
    std::remove(file.c_str());
}

// Line numbers: the header takes lines 1-7, so the first item starts on line 8.
TEST(SteerSuite, StartNearAWallIsLeftOutWithANote) {
    const std::string file = write_case("wall", agent(0, 0, seek(5, 5)) + obstacle(-3, -2, 5, 6) +
                                                    agent(-1.5, 5.5, seek(5, -5)) + agent(9.5, 0, seek(-5, 0)));
    const ImportedScenario s = import(file);
    ASSERT_EQ(s.scenario.agents.size(), 1u);
    EXPECT_EQ(s.scenario.agents[0].start.x, 0.0);
    const auto n = notes_with(s, "to turn on the spot");
    ASSERT_EQ(n.size(), 2u);
    EXPECT_EQ(n[0], file +
                        ":16: agent: starts 0.5 m from a wall or an obstacle; mobb's agents need 0.98 m to turn on "
                        "the spot: left out");
    EXPECT_EQ(n[1].rfind(file + ":23: agent: starts 0.5 m from", 0), 0u) << n[1];
    std::remove(file.c_str());
}

TEST(SteerSuite, StartInsideAnObstacleOrOutsideTheWorld) {
    const std::string file = write_case("inside", obstacle(-3, 3, -3, 3) + agent(0, 0, seek(5, 10)) +
                                                      agent(12, 0, seek(5, 10)) + agent(5, -10, seek(5, 10)));
    const ImportedScenario s = import(file);
    EXPECT_EQ(s.scenario.agents.size(), 1u);
    EXPECT_EQ(notes_with(s, ":9: agent: starts inside an obstacle").size(), 1u);
    EXPECT_EQ(notes_with(s, ":16: agent: starts outside the world: left out").size(), 1u);
    std::remove(file.c_str());
}

TEST(SteerSuite, StartsCloserThanTwoHeldDisks) {
    const std::string file = write_case("close", agent(0, 0, seek(5, 5)) + agent(0.6, 0, seek(-5, -5)));
    const ImportedScenario s = import(file);
    ASSERT_EQ(s.scenario.agents.size(), 1u);
    const auto n = notes_with(s, "two standing agents");
    ASSERT_EQ(n.size(), 1u);
    EXPECT_EQ(n[0],
              file + ":15: agent: starts 0.6 m from the agent at line 8; two standing agents need 0.98 m: left out");
    std::remove(file.c_str());
}

TEST(SteerSuite, NarrowGapIsReported) {
    // A 0.6 m slot between two blocks, a 1.6 m door between two others, and a block 0.5 m from the wall.
    const std::string file =
        write_case("gaps", obstacle(-8, -1, 10, 11) + obstacle(-0.4, 8, 10, 11) + obstacle(-8, -0.8, -10, -9) +
                               obstacle(0.8, 8, -10, -9) + obstacle(-4, 9.5, 0, 1) + agent(0, 5, seek(0, -15)));
    const ImportedScenario s = import(file);
    const auto n = notes_with(s, "leave a gap");
    ASSERT_EQ(n.size(), 2u);
    EXPECT_EQ(n[0], file +
                        ": the obstacle at line 8 and the obstacle at line 9 leave a gap of 0.6 m; mobb's agents "
                        "need 0.96 m to walk through: it stays shut to them");
    EXPECT_EQ(n[1].rfind(file + ": the obstacle at line 12 and the wall x = 10 leave a gap of 0.5 m", 0), 0u) << n[1];
    std::remove(file.c_str());
}

TEST(SteerSuite, GoalSequenceBecomesGoalsInTurn) {
    const std::string file = write_case("sequence", agent(0, 0, seek(5, 5) + seek(-5, 8)));
    const ImportedScenario s = import(file);
    ASSERT_EQ(s.scenario.agents.size(), 1u);
    EXPECT_EQ(s.scenario.agents[0].goals, (std::vector<std::array<double, 2>>{{5, 5}, {-5, 8}}));
    EXPECT_TRUE(notes_with(s, "goal sequence").empty());
    // Through both goals: 7.07 + 10.44 m, twice at 1.38 m/s plus 20 s, in whole tens.
    EXPECT_EQ(s.scenario.time_limit, 50);
    const nlohmann::json j = nlohmann::json::parse(scenario_json(s.scenario));
    EXPECT_EQ(j["at_goal"], "leave");
    EXPECT_EQ(j["agents"][0]["goals"], nlohmann::json::parse("[[5, 5], [-5, 8]]"));
    std::remove(file.c_str());
}

TEST(SteerSuite, AgentsStayWhenAsked) {
    const std::string file = write_case("stay", agent(0, 0, seek(5, 5)) + agent(3, 0, seek(5, 5.5)));
    ImportOptions o;
    o.at_goal = AtGoal::Stay;
    const ImportedScenario stay = import_steersuite(file, kRoom, o);
    EXPECT_EQ(stay.scenario.at_goal, AtGoal::Stay);
    for (const AgentSpec& a : stay.scenario.agents) EXPECT_EQ(a.at_goal, AtGoal::Stay);
    const nlohmann::json j = nlohmann::json::parse(scenario_json(stay.scenario));
    EXPECT_FALSE(j.contains("at_goal"));
    std::remove(file.c_str());
}

TEST(SteerSuite, OtherGoalTypes) {
    const std::string idle = "      <idle> <desiredSpeed>0</desiredSpeed> <timeDuration>5</timeDuration> </idle>\n";
    const std::string file =
        write_case("kinds", agent(0, 0, idle) + agent(4, 0, idle + seek(4, 10)) + region(3, -5, 5, -15, -10, idle));
    const ImportedScenario s = import(file);
    ASSERT_EQ(s.scenario.agents.size(), 1u);
    EXPECT_EQ(s.scenario.agents[0].goals, (std::vector<std::array<double, 2>>{{4, 10}}));
    EXPECT_EQ(notes_with(s,
                         ":8: agent: no seekStaticTarget among its goals (idle); mobb's agents seek one static "
                         "goal: the agent is left out")
                  .size(),
              1u);
    EXPECT_EQ(notes_with(s, ":15: agent: goals mobb's agents do not pursue (idle): dropped").size(), 1u);
    EXPECT_EQ(notes_with(s,
                         ":23: agentRegion: no seekStaticTarget among its goals (idle); mobb's agents seek one "
                         "static goal: its 3 agents are left out")
                  .size(),
              1u);
    std::remove(file.c_str());
}

TEST(SteerSuite, SpeedsRadiiAndSharedGoalsAreReported) {
    const std::string file = write_case("speeds", agent(-5, 0, seek(5, 5, 1.3)) + agent(5, 0, seek(5, 5.5, 2)));
    const ImportedScenario s = import(file);
    EXPECT_EQ(notes_with(s,
                         ": speeds of 0 to 2 m/s ignored: mobb's agents walk at their clips' speeds (1.38 m/s on "
                         "average)")
                  .size(),
              1u);
    EXPECT_EQ(notes_with(s, ": radii of 0.5 m ignored").size(), 1u);
    EXPECT_EQ(notes_with(s, ": time limit ").size(), 1u);
    // Two goals 0.5 m apart: said only when the agents stay at their goals (AgentsStayWhenAsked).
    EXPECT_TRUE(notes_with(s, "of another's").empty());
    ImportOptions stay;
    stay.at_goal = AtGoal::Stay;
    EXPECT_EQ(
        notes_with(import_steersuite(file, kRoom, stay), ": 2 agents have a goal within 0.98 m of another's").size(),
        1u);
    std::remove(file.c_str());
}

TEST(SteerSuite, NothingToRunIsNoAgent) {
    const std::string file = write_case("empty", obstacle(-1, 1, -1, 1));
    EXPECT_TRUE(import(file).scenario.agents.empty());
    std::remove(file.c_str());
}

// Errors: one line, "FILE:LINE: element: message".
std::string write_text(const std::string& name, const std::string& text) {
    const std::string file = test::temp_file(name);
    std::ofstream(file) << text;
    return file;
}

TEST(SteerSuite, NotXmlNamesTheLine) {
    const std::string file = write_text("bad.xml", "<SteerBenchTestCase>\n  <header>\n  </heade>\n");
    EXPECT_EQ(error_of(file), file + ":2: XML: mismatched element <header>");  // where <header> opens
    const std::string empty = write_text("empty.xml", "");
    EXPECT_EQ(error_of(empty), empty + ":1: XML: empty document");
    std::remove(file.c_str());
    std::remove(empty.c_str());
}

TEST(SteerSuite, MissingFileAndWrongRoot) {
    EXPECT_EQ(error_of("/no/such/case.xml"), "/no/such/case.xml: cannot open the test case");
    const std::string file = write_text("root.xml", "<?xml version=\"1.0\"?>\n<scene>\n</scene>\n");
    EXPECT_EQ(error_of(file), file + ":2: scene: expected <SteerBenchTestCase>");
    std::remove(file.c_str());
}

TEST(SteerSuite, MissingRequiredElement) {
    const std::string file = write_text("noworld.xml",
                                        "<SteerBenchTestCase>\n  <header>\n    <version>1.0</version>\n"
                                        "    <name>x</name>\n  </header>\n</SteerBenchTestCase>\n");
    EXPECT_EQ(error_of(file), file + ":2: header: needs <worldBounds>");
    const std::string nogoals = write_case("nogoals",
                                           "  <agent>\n    <initialConditions> <radius>0.5</radius> "
                                           "<position> <x>0</x> <y>0</y> <z>0</z> </position>\n"
                                           "      <direction> <random>true</random> </direction> "
                                           "<speed>0</speed> </initialConditions>\n  </agent>\n");
    EXPECT_EQ(error_of(nogoals), nogoals + ":8: agent: needs <goalSequence>");
    std::remove(file.c_str());
    std::remove(nogoals.c_str());
}

TEST(SteerSuite, NonNumericField) {
    const std::string file = write_case("letters",
                                        "  <obstacle>\n    <xmin>-1</xmin>\n    <xmax>one</xmax>\n    "
                                        "<ymin>0</ymin> <ymax>1</ymax> <zmin>0</zmin> <zmax>1</zmax>\n  "
                                        "</obstacle>\n");
    EXPECT_EQ(error_of(file), file + ":10: xmax: expected a number, got \"one\"");
    const std::string count = write_case("count", region(0, -1, 1, -1, 1, seek(0, 0)));
    EXPECT_TRUE(import(count).scenario.agents.empty());
    std::ofstream(count) << "<SteerBenchTestCase>\n<header> <version>1.0</version> <name>n</name>\n<worldBounds> "
                            "<xmin>0</xmin> <xmax>1</xmax> <ymin>0</ymin> <ymax>0</ymax> <zmin>0</zmin> <zmax>1</zmax> "
                            "</worldBounds> </header>\n<agentRegion>\n<numAgents>ten</numAgents>\n</agentRegion>\n"
                            "</SteerBenchTestCase>\n";
    EXPECT_EQ(error_of(count), count + ":5: numAgents: expected a whole number up to 100000, got \"ten\"");
    std::remove(file.c_str());
    std::remove(count.c_str());
}

TEST(SteerSuite, BadBoxes) {
    const std::string world = write_case("flat", agent(0, 0, seek(1, 1)), "-10 10 0 0 5 5");
    EXPECT_EQ(error_of(world), world + ":6: worldBounds: the ground (x, z) has no area");
    const std::string box = write_case("inverted", obstacle(2, 1, 0, 1));
    EXPECT_EQ(error_of(box), box + ":8: obstacle: xmin is above xmax");
    std::remove(world.c_str());
    std::remove(box.c_str());
}

// The documented defaults are the committed graph's, rounded up.
TEST(SteerSuite, AgentRoomOfTheCommittedGraph) {
    const AgentRoom room = AgentRoom::of(load_graph(kGraph));
    EXPECT_LE(room.wall_clearance, kRoom.wall_clearance);
    EXPECT_GT(room.wall_clearance, kRoom.wall_clearance - 0.01);
    EXPECT_LE(room.hold_radius, kRoom.hold_radius);
    EXPECT_GT(room.hold_radius, kRoom.hold_radius - 0.01);
    EXPECT_LE(room.walk_width, kRoom.walk_width);
    EXPECT_GT(room.walk_width, kRoom.walk_width - 0.01);
    EXPECT_NEAR(room.walk_speed, kRoom.walk_speed, 0.005);
}

}  // namespace
}  // namespace mobb::crowd
