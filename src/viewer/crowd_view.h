// A recorded crowd (`mobb crowd --record FILE`) in the viewer: one disk stack per agent from the
// record's samples, the agents' choice points, and a choice point's candidates placed where the
// agent stood (from the motion graph's clip paths) with the query of a candidate against another
// agent's committed clip opened in the trace debugger, and every agent's skeleton at the time cursor.
// The record is read through crowd::RecordReader: a JSON one whole; a large HDF5 one a window of frames
// around the time cursor at a time (read again as the cursor leaves it) and a choice point when it is
// shown, so that it opens in the time its header, its clips and one window take.
#pragma once
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "crowd_poses.h"
#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/record/record.h"
#include "mobb/crowd/record/record_reader.h"
#include "state.h"

namespace mobb::viewer {

/// A mark on the Crowd panel's timeline strip: a fallback (at its choice point) or a frame with contacts.
struct TimelineMark {
    enum Kind { Fallback, Contact } kind = Fallback;
    std::int64_t frame = 0;
    int agent = 0;    ///< the fallback's agent, or the first agent of the frame's first contact
    int choice = -1;  ///< the fallback's choice point (row in the record's choice table)
    int count = 1;    ///< contacts: agent pairs in contact at that frame
};

/// Most disks (agents x frames) the viewer reads of a record at a time: a record of at most this many is
/// read whole when it opens; a larger one a window of frames around the time cursor, at most this many
/// disks (about 200 bytes each in the viewer with their stacks' trees and draw buffers: 4 M disks, 0.8 GB;
/// 400 frames of 10,000 agents, 13 s, more than the 10 s the crowd's time window draws; 40 of 100,000).
constexpr std::size_t kCrowdWindowDisks = std::size_t(4) << 20;
/// Seconds read either side of the frames drawn (the time window around the cursor), so that playing
/// or scrubbing a little reads nothing.
constexpr double kCrowdReadAhead = 1.0;

struct CrowdView {
    std::shared_ptr<crowd::RecordReader> reader;  ///< the record file (its header: record())
    std::size_t window_disks = kCrowdWindowDisks;
    crowd::SampleWindow window;                            ///< the frames at hand: every agent's disks there
    std::pair<std::int64_t, std::int64_t> unread{-1, -1};  ///< the last frames that could not be read
    std::shared_ptr<crowd::MotionGraph> graph;             ///< null when the record's graph cannot be read
    std::string graph_error;
    std::shared_ptr<PoseSources> poses;        ///< the graph's mocap sources for the skeletons (null without graph)
    std::shared_ptr<crowd::CrowdPoser> poser;  ///< the agents' poses, made on the first skeleton drawn
    std::string pose_error;                    ///< why the poser could not be made (a source failed)
    std::vector<int> bones;                    ///< drawn_bones of the poser's rig
    int agents = 0;                            ///< clips 0..agents-1 of the state are the agents
    int agent = 0;                             ///< agent whose choice points the panel lists
    int choice = -1;                           ///< row of the selected choice point, -1 for none
    crowd::ChoicePoint selected;               ///< that choice point, read whole
    std::map<std::size_t, crowd::ChoicePoint> named;  ///< the choice points its queries name (by row)
    std::vector<int> candidate_clips;              ///< state clip of each candidate of the choice (-1: unknown clip id)
    int opened_candidate = -1, opened_query = -1;  ///< the query shown in the trace debugger, -1 for none
    std::vector<bool> accepted;                    ///< per candidate: no hit, inside the world
    std::vector<crowd::Contact> contacts;          ///< frame_contacts of the window, by frame
    std::vector<crowd::ChoiceMark> fallbacks;      ///< every fallback of the run
    std::map<std::int64_t, TimelineMark> contact_marks;  ///< frames with contacts among those read so far
    std::vector<TimelineMark> marks;                     ///< timeline_marks(), for the Crowd panel
    /// The window's contacts, and the timeline's marks of its frames (anew, after its disks changed).
    void mark_contacts(CrowdView& view);

    /// The listed agent's choice points in the window (agent_choices), and for which agent and window.
    std::vector<crowd::ChoiceSummary> listed;
    int listed_agent = -1;
    std::int64_t listed_first = -1, listed_last = -1;
    bool playing = false;
    float rate = 1.0f;  ///< seconds of crowd per second while playing

    /// The record without samples and choice points: header, world, tracks' goals and clips.
    const crowd::Record& record() const { return reader->header(); }
    /// Whether the window holds every frame of the run.
    bool whole() const { return window.first == 0 && window.last == record().frames; }
};

/// Loads a record and its graph (when readable) into a state: agents as clips, no query. The frames read
/// are all of a record of at most `window_disks` disks, else those around `cursor` (seconds; negative:
/// the middle of the run) for a time window of `window` seconds either side (the scene's; sync_crowd
/// moves them). Throws std::runtime_error naming the file.
State load_crowd_state(const std::string& record_file, float aspect, double cursor = -1, double window = -1,
                       std::size_t window_disks = kCrowdWindowDisks);

/// Frames first .. last - 1 to have at hand for the state's time cursor and window: all of a record of
/// at most window_disks disks; else those drawn and kCrowdReadAhead seconds either side, at most
/// window_disks disks about the cursor.
std::pair<std::int64_t, std::int64_t> crowd_frames_wanted(const State& state);

/// Reads the frames around the time cursor when those drawn are not all at hand, and rebuilds the
/// agents' stacks from them. Returns true when it read. Throws std::runtime_error naming the file and
/// the block for a damaged file.
bool sync_crowd(State& state);

/// The window's contacts, and the timeline's marks of its frames (anew, after its disks changed).
void mark_contacts(CrowdView& view);

/// The listed agent's choice points in the window (every one of a record read whole), in time order.
const std::vector<crowd::ChoiceSummary>& agent_choices(CrowdView& view, int agent);

/// Selects an agent (-1 keeps it) and one of the record's choice points (its row; -1 for none), read
/// whole with the choice points its queries name: the candidates are added as extra clips after the
/// agents, coloured accepted / rejected.
void select_choice(State& state, int agent, int choice);

/// Rebuilds query j of candidate k of the selected choice (candidate.against[j]: the candidate placed
/// where the agent stood against another agent's clip, committed or reserved, as the crowd ran it) as
/// the state's query with a trace, shown from its first step. Returns false, with the reason in
/// `message`, for a query that was not clip against clip (held ground, walls, obstacles, or asked by an
/// escape clip of the candidate) or when the record or the graph lacks what it needs; else `message`
/// gives the answer and the recorded one.
bool open_candidate_query(State& state, int k, int j, std::string* message = nullptr);

/// The clip query `q` of the selected choice point met (crowd::query_clip, the choice points it names
/// from CrowdView::named); nothing for held ground and solids. Throws std::out_of_range for a bad query.
std::optional<crowd::FramedClip> query_clip(const CrowdView& view, const crowd::CandidateQuery& q);

/// The space-time a crowd read in windows spans: its world over the whole run (empty for one read
/// whole, whose stacks span it), so that framing it frames the run, not the frames at hand.
render::Bounds crowd_extent(const CrowdView& view);

/// Why skeletons are missing ("" when none is): no graph, or a source failed.
std::string skeleton_problem(const CrowdView& view);

/// Every agent's skeleton at time t (loads every source of the graph on first use: the poses' joints are
/// those all sources share), coloured like its disks.
/// With `planted`, a mark under each planted foot is appended to it (crowd_skeletons).
std::vector<render::PosedSkeleton> agent_skeletons(CrowdView& view, double t, const std::vector<glm::vec3>& colors,
                                                   std::vector<render::Prism>* planted = nullptr);

/// What the 3D view draws besides the agents: the world's walls, the obstacles (filled), each goal as a
/// post in its agent's colour over the whole run, and red rings around the disks in contact at time t.
std::vector<render::Prism> crowd_prisms(const CrowdView& view, double t);

/// Every fallback and every frame with contacts among the frames read so far (all of a record read
/// whole), by frame.
std::vector<TimelineMark> timeline_marks(const CrowdView& view);
/// The mark nearest frame `frame` within `reach` frames, or null.
const TimelineMark* nearest_mark(const std::vector<TimelineMark>& marks, std::int64_t frame, std::int64_t reach);
/// Jumps to a mark: the cursor to its frame; a fallback's choice point selected, or a contact's agent.
void jump_to(State& state, const TimelineMark& mark);

/// Advances the time cursor while playing (wraps at the end).
void update_crowd_playback(State& state, double seconds);

}  // namespace mobb::viewer
