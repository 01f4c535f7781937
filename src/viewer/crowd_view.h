// A recorded crowd (`mobb crowd --record FILE`) in the viewer: one disk stack per agent from the
// record's samples, the agents' choice points, and a choice point's candidates placed where the
// agent stood (from the motion graph's clip paths) with the query of a candidate against another
// agent's committed clip opened in the trace debugger, and every agent's skeleton at the time cursor.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "crowd_poses.h"
#include "mobb/crowd/motion_graph.h"
#include "mobb/crowd/record.h"
#include "state.h"

namespace mobb::viewer {

/// A mark on the Crowd panel's timeline strip: a fallback (at its choice point) or a frame with contacts.
struct TimelineMark {
    enum Kind { Fallback, Contact } kind = Fallback;
    std::int64_t frame = 0;
    int agent = 0;    ///< the fallback's agent, or the first agent of the frame's first contact
    int choice = -1;  ///< the fallback's choice point (index in record.choices)
    int count = 1;    ///< contacts: agent pairs in contact at that frame
};
struct CrowdView {
    crowd::Record record;
    std::shared_ptr<crowd::MotionGraph> graph;  ///< null when the record's graph cannot be read
    std::string graph_error;
    std::shared_ptr<PoseSources> poses;            ///< the graph's mocap sources for the skeletons (null without graph)
    std::shared_ptr<crowd::CrowdPoser> poser;      ///< the agents' poses, made on the first skeleton drawn
    std::string pose_error;                        ///< why the poser could not be made (a source failed)
    std::vector<int> bones;                        ///< drawn_bones of the poser's rig
    int agents = 0;                                ///< clips 0..agents-1 of the state are the agents
    int agent = 0;                                 ///< agent whose choice points the panel lists
    int choice = -1;                               ///< index into record.choices, -1 for none
    std::vector<int> candidate_clips;              ///< state clip of each candidate of the choice (-1: unknown clip id)
    int opened_candidate = -1, opened_query = -1;  ///< the query shown in the trace debugger, -1 for none
    std::vector<bool> accepted;                    ///< per candidate: no hit, inside the world
    std::vector<crowd::Contact> contacts;          ///< frame_contacts(record), by frame
    std::vector<TimelineMark> marks;               ///< timeline_marks(), for the Crowd panel
    bool playing = false;
    float rate = 1.0f;  ///< seconds of crowd per second while playing
};

/// Loads a record and its graph (when readable) into a state: agents as clips, no query.
/// Throws std::runtime_error naming the file.
State load_crowd_state(const std::string& record_file, float aspect);

/// Indices into record.choices of one agent's choice points, in time order.
std::vector<int> agent_choices(const CrowdView& view, int agent);

/// The agent's committed clip started at a choice point (its placement is the candidates' too:
/// every successor starts at the exit pose of the clip before). Null when none.
const crowd::PlacedClip* committed_at(const CrowdView& view, const crowd::ChoicePoint& c);

/// Selects an agent (-1 keeps it) and one of the record's choice points (-1 for none): the
/// candidates are added as extra clips after the agents, coloured accepted / rejected.
void select_choice(State& state, int agent, int choice);

/// Rebuilds query j of candidate k of the selected choice (candidate.against[j]: the candidate placed
/// where the agent stood against another agent's clip, committed or reserved, as the crowd ran it) as
/// the state's query with a trace, shown from its first step. Returns false, with the reason in
/// `message`, for a query that was not clip against clip (held ground, walls, obstacles, or asked by an
/// escape clip of the candidate) or when the record or the graph lacks what it needs; else `message`
/// gives the answer and the recorded one.
bool open_candidate_query(State& state, int k, int j, std::string* message = nullptr);

/// Why skeletons are missing ("" when none is): no graph, or a source failed.
std::string skeleton_problem(const CrowdView& view);

/// Every agent's skeleton at time t (loads every source of the graph on first use: the poses' joints are
/// those all sources share), coloured like its disks.
std::vector<render::PosedSkeleton> agent_skeletons(CrowdView& view, double t, const std::vector<glm::vec3>& colors);

/// What the 3D view draws besides the agents: the world's walls, the obstacles (filled), each goal as a
/// post in its agent's colour over the whole run, and red rings around the disks in contact at time t.
std::vector<render::Prism> crowd_prisms(const CrowdView& view, double t);

/// Every fallback and every frame with contacts, by frame.
std::vector<TimelineMark> timeline_marks(const CrowdView& view);
/// The mark nearest frame `frame` within `reach` frames, or null.
const TimelineMark* nearest_mark(const std::vector<TimelineMark>& marks, std::int64_t frame, std::int64_t reach);
/// Jumps to a mark: the cursor to its frame; a fallback's choice point selected, or a contact's agent.
void jump_to(State& state, const TimelineMark& mark);

/// Advances the time cursor while playing (wraps at the end).
void update_crowd_playback(State& state, double seconds);

}  // namespace mobb::viewer
