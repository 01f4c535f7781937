// SteerSuite test cases imported as scenarios, on small files written here in SteerSuite's schema: the
// mapping of coordinates and of every obstacle and agent kind (circles, oriented boxes and walls, polygons,
// emitters, goal kinds), repaired headers and bounds, random agent and obstacle regions (counts, room,
// determinism), starts moved to where an agent has room, every note, every error with its line, and the
// result run by the crowd.
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
#include "scenario/steersuite_shapes.h"

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

// Line numbers: the header takes lines 1-7, so the first item starts on line 8. A start given with no room
// to stand near a wall or an obstacle moves to the nearest place (to the centimetre, within 1 m) where it
// has room; one with room to stand but not to turn round stays, facing along the wall the way nearer its own.
TEST(SteerSuite, StartNearAWallStandsAndFacesAlongIt) {
    const std::string file = write_case("wall", agent(0, 0, seek(5, 5)) + obstacle(-3, -2, 5, 6) +
                                                    agent(-1.5, 5.5, seek(5, -5), xyz(1, 0, 0.2)) +
                                                    agent(9.2, 0, seek(-5, 0), xyz(1, 0, 0.2)));
    const ImportedScenario s = import(file);
    ASSERT_EQ(s.scenario.agents.size(), 3u);
    EXPECT_EQ(s.scenario.agents[0].start.x, 0.0);
    EXPECT_EQ(s.scenario.agents[0].start.theta, 0.0);     // facing +x, as the file says: room to turn
    const Placement& block = s.scenario.agents[1].start;  // 0.5 m from the block's edge x = -2: 0.59 needed
    EXPECT_EQ(block.x, -1.41);
    EXPECT_EQ(block.y, 5.5);
    EXPECT_NEAR(degrees(block.theta), 90, 1e-6);         // along the edge, the way nearer its own (11.3 degrees)
    const Placement& wall = s.scenario.agents[2].start;  // 0.8 m from the wall x = 10: stands, cannot turn
    EXPECT_EQ(wall.x, 9.2);
    EXPECT_NEAR(degrees(wall.theta), 90, 1e-6);
    ASSERT_EQ(notes_with(s, "to stand: moved").size(), 1u);
    EXPECT_EQ(notes_with(s, "to stand: moved")[0],
              file +
                  ":16: agent: starts 0.5 m from a wall or an obstacle; mobb's agents need 0.59 m to stand: moved "
                  "0.09 m to (-1.41, 5.5), the nearest place with room");
    const auto along = notes_with(s, "faces along it");
    ASSERT_EQ(along.size(), 2u);
    EXPECT_EQ(along[1], file +
                            ":23: agent: starts 0.8 m from a wall or an obstacle: room to stand, not to turn round "
                            "(0.98 m); faces along it, heading 90 degrees (turned 78.69)");
    for (const AgentSpec& a : s.scenario.agents)
        for (const Polygon& p : s.scenario.world.solids())
            EXPECT_FALSE(disk_overlaps(p, a.start.x, a.start.y, kRoom.stand_clearance));
    std::remove(file.c_str());
}

// No room within 1 m (inside a 6 m block), or outside the world by more than 1 m: left out. (The world is
// SteerSuite's own ground here, as a start lies outside the header's bounds: InvertedWorldBounds.)
TEST(SteerSuite, StartInsideAnObstacleOrOutsideTheWorld) {
    const std::string file = write_case("inside", obstacle(-3, 3, -3, 3) + agent(0, 0, seek(5, 10)) +
                                                      agent(102, 0, seek(5, 10)) + agent(5, -10, seek(5, 10)));
    const ImportedScenario s = import(file);
    EXPECT_EQ(s.scenario.world.x1, 100);
    ASSERT_EQ(s.scenario.agents.size(), 1u);
    EXPECT_EQ(s.scenario.agents[0].start.x, 5.0);
    EXPECT_EQ(notes_with(s,
                         ":9: agent: starts inside an obstacle; mobb's agents need 0.59 m to stand, and no "
                         "place within 1 m has room: left out")
                  .size(),
              1u);
    EXPECT_EQ(notes_with(s, ":16: agent: starts outside the world, and no place within 1 m has room: left out").size(),
              1u);
    std::remove(file.c_str());
}

TEST(SteerSuite, StartsCloserThanTwoHeldDisks) {
    const std::string file = write_case("close", agent(0, 0, seek(5, 5)) + agent(0.6, 0, seek(-5, -5)));
    const ImportedScenario s = import(file);
    ASSERT_EQ(s.scenario.agents.size(), 2u);
    EXPECT_EQ(s.scenario.agents[1].start.x, 0.98);
    EXPECT_EQ(s.scenario.agents[1].start.y, 0.0);
    const auto n = notes_with(s, "two standing agents");
    ASSERT_EQ(n.size(), 1u);
    EXPECT_EQ(n[0], file +
                        ":15: agent: starts 0.6 m from the agent at line 8; two standing agents need 0.98 m: moved "
                        "0.38 m to (0.98, 0), the nearest place with room");
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

// idle: at the end the agent stands (at its last goal, or its start), between goals it is dropped; goals
// with no mobb counterpart are dropped, and an agent left with none stands at its start.
TEST(SteerSuite, OtherGoalTypes) {
    const std::string idle = "      <idle> <desiredSpeed>0</desiredSpeed> <timeDuration>5</timeDuration> </idle>\n";
    const std::string flee =
        "      <fleeDynamicTarget> <targetName>A</targetName> <desiredSpeed>1</desiredSpeed> "
        "<timeDuration>9</timeDuration> </fleeDynamicTarget>\n";
    const std::string file =
        write_case("kinds", agent(0, 0, idle) + agent(4, 0, idle + seek(4, 10)) + agent(-4, 0, seek(-4, 10) + idle) +
                                agent(0, -5, flee) + region(3, -5, 5, -15, -10, idle));
    const ImportedScenario s = import(file);
    const auto& a = s.scenario.agents;
    ASSERT_EQ(a.size(), 7u);
    EXPECT_EQ(a[0].goals, (std::vector<std::array<double, 2>>{{0, 0}}));  // stands at its start
    EXPECT_EQ(a[0].at_goal, AtGoal::Stay);
    EXPECT_EQ(a[1].goals, (std::vector<std::array<double, 2>>{{4, 10}}));  // the pause before is dropped
    EXPECT_EQ(a[1].at_goal, AtGoal::Leave);
    EXPECT_EQ(a[2].goals, (std::vector<std::array<double, 2>>{{-4, 10}}));  // stands at its last goal
    EXPECT_EQ(a[2].at_goal, AtGoal::Stay);
    EXPECT_EQ(a[3].goals, (std::vector<std::array<double, 2>>{{0, -5}}));  // nothing left: stands at its start
    EXPECT_EQ(a[3].at_goal, AtGoal::Stay);
    for (std::size_t k = 4; k < 7; ++k) {
        EXPECT_EQ(a[k].goals, (std::vector<std::array<double, 2>>{{a[k].start.x, a[k].start.y}}));
        EXPECT_EQ(a[k].at_goal, AtGoal::Stay);
    }
    const std::string stands =
        "idle: the agent stands at its last goal (at its start if it has none) to the end of the run, at_goal "
        "\"stay\" (SteerSuite's idle 5 s)";
    EXPECT_EQ(notes_with(s, ":12: " + stands).size(), 1u);
    EXPECT_EQ(notes_with(s,
                         ":19: idle: mobb's agents do not wait between goals: dropped, the agent heads on at once "
                         "(SteerSuite's idle 5 s)")
                  .size(),
              1u);
    EXPECT_EQ(notes_with(s, ":28: " + stands).size(), 1u);
    EXPECT_EQ(notes_with(s,
                         ":35: fleeDynamicTarget: its target is agent \"A\": mobb's goals are fixed points, not "
                         "other agents: dropped")
                  .size(),
              1u);
    EXPECT_EQ(notes_with(s,
                         ":31: agent: no goal mobb's agents pursue is left: the agent stands at its start to the end "
                         "of the run (its goal is its start, at_goal \"stay\")")
                  .size(),
              1u);
    // The scenario's agents leave; those that stand say so themselves.
    const nlohmann::json j = nlohmann::json::parse(scenario_json(s.scenario));
    EXPECT_EQ(j["at_goal"], "leave");
    EXPECT_EQ(j["agents"][0]["at_goal"], "stay");
    EXPECT_FALSE(j["agents"][1].contains("at_goal"));
    std::remove(file.c_str());
}

// seekAxisAlignedBoxRegion: its targetLocation is the goal; a <Behaviour> per goal is reported, once.
TEST(SteerSuite, BoxGoalAndBehaviours) {
    const std::string box =
        "      <seekAxisAlignedBoxRegion> <targetLocation> " + xyz(8, 0, 3) +
        " </targetLocation> <desiredSpeed>1.3</desiredSpeed> <timeDuration>100</timeDuration>\n"
        "        <goalRegionBounds> <xmin>6</xmin> <xmax>10</xmax> <ymin>0</ymin> <ymax>0</ymax> <zmin>-6</zmin> "
        "<zmax>6</zmax> </goalRegionBounds> </seekAxisAlignedBoxRegion>\n";
    const std::string behaviour =
        "      <seekStaticTarget> <targetLocation> " + xyz(-5, 0, 5) +
        " </targetLocation> <desiredSpeed>1</desiredSpeed> <timeDuration>10</timeDuration>\n"
        "        <Behaviour> <SteeringAlgorithm>pprAI</SteeringAlgorithm> </Behaviour> </seekStaticTarget>\n";
    const std::string file = write_case("box", agent(0, 0, box) + agent(0, -5, behaviour + behaviour));
    const ImportedScenario s = import(file);
    ASSERT_EQ(s.scenario.agents.size(), 2u);
    EXPECT_EQ(s.scenario.agents[0].goals, (std::vector<std::array<double, 2>>{{8, 3}}));
    EXPECT_EQ(s.scenario.agents[0].at_goal, AtGoal::Leave);
    EXPECT_EQ(notes_with(s,
                         ":12: seekAxisAlignedBoxRegion: a goal at its targetLocation (8, 3), reached within the goal "
                         "radius; SteerSuite's agents also reach it by touching its box (x 6 to 10, z -6 to 6)")
                  .size(),
              1u);
    EXPECT_EQ(notes_with(s, ": 2 goals name a <Behaviour> (SteerSuite's steering algorithm").size(), 1u);
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
    EXPECT_EQ(notes_with(import_steersuite(file, kRoom, stay),
                         ": 2 agents that stay at their goal have one within 0.98 m of another's")
                  .size(),
              1u);
    std::remove(file.c_str());
}

// A test case with no agent is a map: its world alone, and a note.
TEST(SteerSuite, NoAgentIsAMap) {
    const std::string file = write_case("empty", obstacle(-1, 1, -1, 1));
    const ImportedScenario s = import(file);
    EXPECT_TRUE(s.scenario.agents.empty());
    EXPECT_EQ(s.case_agents, 0);
    EXPECT_EQ(s.scenario.world.obstacles.size(), 1u);
    EXPECT_EQ(notes_with(s, file + ": the test case has no agent: the scenario is its world alone, a map").size(), 1u);
    const Scenario back = parse_scenario(nlohmann::json::parse(scenario_json(s.scenario)), "map");
    EXPECT_TRUE(back.agents.empty());
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

// Bounds with no area, or an obstacle's min above its max: repaired with a note, as SteerSuite reads them.
TEST(SteerSuite, FlatWorldAndInvertedObstacle) {
    const std::string world = write_case("flat", agent(0, 0, seek(1, 1)), "-10 10 0 0 5 5");
    const ImportedScenario flat = import(world);
    const World& w = flat.scenario.world;
    EXPECT_EQ(std::vector<double>({w.x0, w.y0, w.x1, w.y1}), std::vector<double>({-100, -100, 100, 100}));
    EXPECT_EQ(notes_with(flat, world + ":6: worldBounds: the ground (x, z) has no area; 2 of the 2 positions the file "
                                       "gives (starts, goals) lie outside: the world is SteerSuite's own ground")
                  .size(),
              1u);
    const std::string box = write_case("inverted", obstacle(2, 1, 0, 1) + agent(-5, 0, seek(-5, 5)));
    const ImportedScenario inverted = import(box);
    ASSERT_EQ(inverted.scenario.world.obstacles.size(), 1u);
    EXPECT_EQ(inverted.scenario.world.obstacles[0].vertices, Polygon::rectangle(1, 0, 2, 1).vertices);
    EXPECT_EQ(notes_with(inverted, box + ":8: obstacle: xmin 2 is above xmax 1: read with min and max swapped").size(),
              1u);
    std::remove(world.c_str());
    std::remove(box.c_str());
}

// Public files open with a comment before the XML declaration, which XML does not allow: read as
// SteerSuite reads them, lines unchanged.
TEST(SteerSuite, CommentBeforeTheDeclaration) {
    const std::string items = agent(0, 0, seek(5, 5));
    const std::string text =
        "<!--\n  a licence, two lines\n--><?xml version=\"1.0\" ?>\n"
        "<SteerBenchTestCase xmlns=\"http://www.magix.ucla.edu/steerbench\">\n"
        "  <header> <version>1.0</version> <name>declared</name>\n"
        "    <worldBounds> <xmin>-10</xmin> <xmax>10</xmax> <ymin>0</ymin> <ymax>0</ymax> "
        "<zmin>-20</zmin> <zmax>20</zmax> </worldBounds> </header>\n" +
        items + "</SteerBenchTestCase>\n";
    const std::string file = test::temp_file("declared.xml");
    std::ofstream(file) << text;
    const ImportedScenario s = import(file);
    EXPECT_EQ(s.scenario.name, "declared");
    ASSERT_EQ(s.scenario.agents.size(), 1u);
    EXPECT_EQ(s.scenario.agents[0].goals, (std::vector<std::array<double, 2>>{{5, 5}}));
    std::ofstream(file) << std::string(text).replace(text.find("<x>5</x>"), 8, "<x>five</x>");
    EXPECT_EQ(error_of(file), file + ":11: x: expected a number, got \"five\"");  // the lines the file has
    std::ofstream(file) << "<!-- c --> <?xml version=\"1.0\"?>\n<SteerBenchTestCase>\n  <header>\n  </heade>\n";
    EXPECT_EQ(error_of(file), file + ":3: XML: mismatched element <header>");
    std::remove(file.c_str());
}

// Inverted bounds that hold the file's positions once swapped are swapped; those that do not (as in
// circle-10, xmin -100 above xmax -200 with agents about the origin) give SteerSuite's own ground.
TEST(SteerSuite, InvertedWorldBounds) {
    const std::string swapped = write_case("swapped", agent(0, 0, seek(5, 15)), "10 -10 0 0 20 -20");
    const ImportedScenario a = import(swapped);
    const World& w = a.scenario.world;
    EXPECT_EQ(std::vector<double>({w.x0, w.y0, w.x1, w.y1}), std::vector<double>({-10, -20, 10, 20}));
    ASSERT_EQ(a.scenario.agents.size(), 1u);
    EXPECT_EQ(
        notes_with(a, swapped + ":6: worldBounds: xmin 10 is above xmax -10 and zmin 20 is above zmax -20: read with "
                                "min and max swapped")
            .size(),
        1u);
    const std::string away =
        write_case("away", agent(2, 1, seek(-8, -9)) + agent(-9, 9, seek(9, -9)), "-100 -200 0 0 -100 -200");
    const ImportedScenario b = import(away);
    const World& g = b.scenario.world;
    EXPECT_EQ(std::vector<double>({g.x0, g.y0, g.x1, g.y1}), std::vector<double>({-100, -100, 100, 100}));
    ASSERT_EQ(b.scenario.agents.size(), 2u);
    EXPECT_EQ(b.scenario.agents[0].start.x, 2.0);
    EXPECT_EQ(b.scenario.agents[0].goals, (std::vector<std::array<double, 2>>{{-8, -9}}));
    EXPECT_EQ(
        notes_with(b, away + ":6: worldBounds: xmin -100 is above xmax -200 and zmin -100 is above zmax -200; 4 of "
                             "the 4 positions the file gives (starts, goals) lie outside the bounds swapped: the "
                             "world is SteerSuite's own ground, x and z from -100 to 100 (its simulation grid; its "
                             "reader uses worldBounds only to place random agents and obstacles)")
            .size(),
        1u);
    // An agentRegion's bounds, zmin above zmax: swapped, its agents drawn between them.
    const std::string region_file = write_case("region_swapped", region(4, -5, 5, 0, -6, seek(0, 10)));
    const ImportedScenario c = import(region_file);
    ASSERT_EQ(c.scenario.agents.size(), 4u);
    for (const AgentSpec& agent : c.scenario.agents) EXPECT_TRUE(agent.start.y >= -6 && agent.start.y <= 0);
    EXPECT_EQ(notes_with(c, ":8: agentRegion: its regionBounds' zmin 0 is above zmax -6: read with min and max swapped")
                  .size(),
              1u);
    std::remove(swapped.c_str());
    std::remove(away.c_str());
    std::remove(region_file.c_str());
}

std::string circle_obstacle(double x, double z, double r) {
    std::ostringstream s;
    s << "  <circleObstacle> <radius>" << r << "</radius> <height>1</height> <position> " << xyz(x, 0, z)
      << " </position> </circleObstacle>\n";
    return s.str();
}

std::string oriented_box(double x, double z, double lx, double lz, double theta, const std::string& door = "") {
    std::ostringstream s;
    s << "  <" << (door.empty() ? "orientedBoxObstacle" : "orientedWallObstacle") << "> <thetaY>" << theta
      << "</thetaY> <size> " << xyz(lx, 1, lz) << " </size> <position> " << xyz(x, 0, z) << " </position> " << door
      << "</" << (door.empty() ? "orientedBoxObstacle" : "orientedWallObstacle") << ">\n";
    return s.str();
}

// The distance from the centre to each edge's line (the polygon is convex, in order).
std::vector<double> edge_distances(const Polygon& p, double x, double y) {
    std::vector<double> out;
    const auto& v = p.vertices;
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
        const double ex = v[i][0] - v[j][0], ey = v[i][1] - v[j][1];
        out.push_back(std::abs(ex * (y - v[j][1]) - ey * (x - v[j][0])) / std::hypot(ex, ey));
    }
    return out;
}

// A circle becomes the regular polygon around it: the fewest sides whose corners stay within 1 cm, every
// edge outside the circle (so a disk clear of the polygon is clear of the circle).
TEST(SteerSuite, CircleObstacleIsAPolygonAroundIt) {
    const std::string file = write_case("circles", circle_obstacle(3, 4, 1) + circle_obstacle(-5, -10, 2) +
                                                       circle_obstacle(9.5, 0, 1) + agent(-5, 5, seek(5, 15)));
    const ImportedScenario s = import(file);
    const auto& obstacles = s.scenario.world.obstacles;
    ASSERT_EQ(obstacles.size(), 3u);
    EXPECT_EQ(obstacles[0].vertices.size(), 23u);
    EXPECT_EQ(obstacles[1].vertices.size(), 32u);
    EXPECT_EQ(obstacles[0].vertices[0], (std::array<double, 2>{4.009403, 4}));  // a corner at angle 0
    for (const double d : edge_distances(obstacles[0], 3, 4)) EXPECT_TRUE(d >= 1 && d < 1 + 2e-6) << d;
    for (const double d : edge_distances(obstacles[1], -5, -10)) EXPECT_TRUE(d >= 2 && d < 2 + 2e-6) << d;
    for (const auto& v : obstacles[0].vertices) EXPECT_LE(std::hypot(v[0] - 3, v[1] - 4), 1.01);
    for (int k = 0; k < 3600; ++k) {  // every point of the circle is inside: a disk touching it overlaps
        const double a = radians(k / 10.0);
        EXPECT_TRUE(disk_overlaps(obstacles[0], 3 + std::cos(a), 4 + std::sin(a), 1e-9)) << k;
    }
    // One that crosses the wall x = 10 is clipped to the world.
    for (const auto& v : obstacles[2].vertices) EXPECT_LE(v[0], 10);
    EXPECT_EQ(bounds(obstacles[2])[2], 10);
    EXPECT_EQ(notes_with(s,
                         ":8: circleObstacle: radius 1 m at (3, 4): a regular 23-gon around the circle, its corners "
                         "9.4 mm beyond it (the fewest sides, at least 8, within 1 cm): it holds the whole circle, "
                         "so collisions stay conservative")
                  .size(),
              1u);
    EXPECT_EQ(notes_with(s, ":9: circleObstacle: radius 2 m at (-5, -10): a regular 32-gon").size(), 1u);
    EXPECT_TRUE(notes_with(s, "not an element").empty());
    std::remove(file.c_str());
}

TEST(SteerSuite, CircleSides) {
    EXPECT_EQ(steersuite::circle_sides(0.5), 16);
    EXPECT_EQ(steersuite::circle_sides(1), 23);
    EXPECT_EQ(steersuite::circle_sides(5), 50);
    EXPECT_EQ(steersuite::circle_sides(100), 223);
    EXPECT_EQ(steersuite::circle_sides(0.01), 8);
    EXPECT_EQ(steersuite::circle_sides(1000), 256);
    for (const double r : {0.5, 1.0, 5.0, 100.0}) EXPECT_LE(steersuite::circle_reach(r), 0.01);
}

// An oriented box is its rectangle turned as SteerSuite turns it (thetaY 20: its own x axis points to
// (cos 20, -sin 20) in mobb's ground); an oriented wall is two sections either side of its door.
TEST(SteerSuite, OrientedBoxAndWall) {
    const std::string door = "<doorway> <value>1</value> <doorRadius>0.5</doorRadius> </doorway> ";
    const std::string file = write_case(
        "oriented", oriented_box(1, 2, 2, 1, 20) + oriented_box(0, 5, 10, 0.5, 0, door) + agent(-5, -10, seek(5, -10)));
    const ImportedScenario s = import(file);
    const auto& obstacles = s.scenario.world.obstacles;
    ASSERT_EQ(obstacles.size(), 3u);
    const std::vector<std::array<double, 2>> turned{
        {-0.110703, 1.872174}, {1.768683, 1.188134}, {2.110703, 2.127826}, {0.231317, 2.811866}};
    ASSERT_EQ(obstacles[0].vertices.size(), 4u);
    for (std::size_t k = 0; k < 4; ++k) {
        EXPECT_NEAR(obstacles[0].vertices[k][0], turned[k][0], 1e-6) << k;
        EXPECT_NEAR(obstacles[0].vertices[k][1], turned[k][1], 1e-6) << k;
    }
    EXPECT_EQ(obstacles[1].vertices, Polygon::rectangle(-5, 4.75, 0.5, 5.25).vertices);   // to the door at 1 - 0.5
    EXPECT_EQ(obstacles[2].vertices, Polygon::rectangle(1.5, 4.75, 4.5, 5.25).vertices);  // as SteerSuite builds it
    EXPECT_EQ(notes_with(s,
                         ":9: orientedWallObstacle: a wall of 10 m with a door 1 m wide at 1 m from its centre: two "
                         "sections where SteerSuite builds them (the second ends 0.5 m short of the wall's end)")
                  .size(),
              1u);
    EXPECT_TRUE(notes_with(s, ":8:").empty());  // the box is SteerSuite's exactly: nothing to say
    std::remove(file.c_str());
}

// A polygon as given; obstacles at a random position (SteerSuite's reader places none) are left out; the
// gaps between shapes are their true distances.
TEST(SteerSuite, PolygonRandomObstacleAndGaps) {
    const std::string polygon = "  <polygonObstacle> <vertex> " + xyz(-5, 0, 10) + " </vertex> <vertex> " +
                                xyz(-3, 0, 10) + " </vertex> <vertex> " + xyz(-4, 0, 12) +
                                " </vertex> </polygonObstacle>\n";
    const std::string random =
        "  <circleObstacle> <radius>1</radius> <height>1</height> <position> <random>true</random> </position> "
        "</circleObstacle>\n";
    const std::string file = write_case(
        "shapes", polygon + random + circle_obstacle(0, 0, 1) + obstacle(1, 3, 1, 3) + agent(-5, -10, seek(5, -10)));
    const ImportedScenario s = import(file);
    const auto& obstacles = s.scenario.world.obstacles;
    ASSERT_EQ(obstacles.size(), 3u);
    EXPECT_EQ(obstacles[0].vertices, (std::vector<std::array<double, 2>>{{-5, 10}, {-3, 10}, {-4, 12}}));
    EXPECT_EQ(
        notes_with(s,
                   ":9: circleObstacle: a random position, size or door: SteerSuite's reader places no such obstacle "
                   "(it draws only obstacleRegion squares): left out")
            .size(),
        1u);
    // The box's corner (1, 1) is 1.414 m from the circle's centre: 0.41 m from its polygon (their bounds touch).
    EXPECT_EQ(notes_with(s,
                         ": the circleObstacle at line 10 and the obstacle at line 11 leave a gap of 0.41 m; mobb's "
                         "agents need 0.96 m to walk through: it stays shut to them")
                  .size(),
              1u);
    std::remove(file.c_str());
}

// An emitter gives the one agent SteerSuite emits first, with its goal sequence; two at one ground point
// (SteerSuite's heights differ) become two agents, the second moved to where it has room.
TEST(SteerSuite, EmitterGivesItsFirstAgent) {
    const std::string emitter =
        "  <agentEmitter> <name>E</name>\n    <initialConditions> <radius>0.5</radius> <position> " + xyz(-1, 0, 0) +
        " </position>\n      <direction> " + xyz(0, 0, -1) +
        " </direction> <speed>0</speed> </initialConditions>\n    <goalSequence>\n" + seek(-1, 4) + seek(2, 4) +
        "    </goalSequence>\n  </agentEmitter>\n";
    const std::string file = write_case("emitter", emitter + emitter);
    const ImportedScenario s = import(file);
    const auto& a = s.scenario.agents;
    ASSERT_EQ(a.size(), 2u);
    EXPECT_EQ(a[0].start.x, -1.0);
    EXPECT_EQ(a[0].start.y, 0.0);
    EXPECT_NEAR(degrees(a[0].start.theta), -90, 1e-12);
    EXPECT_EQ(a[0].start_time, 0.0);
    EXPECT_EQ(a[0].goals, (std::vector<std::array<double, 2>>{{-1, 4}, {2, 4}}));
    EXPECT_EQ(a[0].at_goal, AtGoal::Leave);
    EXPECT_NEAR(std::hypot(a[1].start.x + 1, a[1].start.y), 0.98, 1e-9);
    EXPECT_EQ(a[1].goals, a[0].goals);
    const std::string note =
        "agentEmitter: mobb keeps the first agent it emits, as an agent from the start (SteerSuite emits it at "
        "once), not the ones it emits again, one each time the last finishes its goals: a mobb agent holds its "
        "start from the first frame (start_time only delays its first step), so no two can share the emitter's "
        "start";
    EXPECT_EQ(notes_with(s, file + ":8: " + note).size(), 1u);
    EXPECT_EQ(notes_with(s, file + ":16: " + note).size(), 1u);
    EXPECT_EQ(notes_with(s,
                         ":16: agentEmitter: starts 0 m from the agent at line 8; two standing agents need 0.98 m: "
                         "moved 0.98 m")
                  .size(),
              1u);
    std::remove(file.c_str());
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
