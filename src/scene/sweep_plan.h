#pragma once
// A parameter sweep (`lenslab sweep SCENE --set POINTER=FROM:TO:COUNT`): which number of the
// scene's JSON changes, its value in each frame, and which frames a process of a cluster
// renders. JSON only: the scene reader checks each frame's scene as it checks a file.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "util/error.h"

namespace lenslab {

// A --set that does not parse, sweeps that disagree, or a pointer the scene cannot take.
class SweepError : public Error {
public:
    using Error::Error;
};

// One swept number: `pointer` (RFC 6901, e.g. /objects/1/center/2) runs linearly from `from`
// to `to`, both included, over `count` frames (count 1: `from` alone).
struct SweepParameter {
    std::string pointer;
    double from = 0, to = 0;
    int count = 1;
};

// Parses "POINTER=FROM:TO:COUNT". Throws SweepError naming the part that is wrong.
SweepParameter parse_sweep_parameter(const std::string& text);

// The parameter's value in frame `frame` (0-based); exactly `from` and `to` at the ends.
double sweep_value(const SweepParameter& parameter, int frame);

// Several parameters change together, frame by frame, so they must have one count.
struct SweepPlan {
    std::vector<SweepParameter> parameters;
    int count = 0;
};

// Parses each --set; throws SweepError when there is none or their counts differ.
SweepPlan parse_sweep_plan(const std::vector<std::string>& sets);

// Throws SweepError unless every pointer of `plan` names a number in `scene`: a missing path
// names the deepest part that exists, a value of another kind is quoted.
void check_sweep_targets(const nlohmann::json& scene, const SweepPlan& plan);

// `scene` with frame `frame`'s values in place (check_sweep_targets first).
nlohmann::json sweep_frame_json(nlohmann::json scene, const SweepPlan& plan, int frame);

// The frames process `rank` of `size` renders: round-robin (rank, rank + size, ...), so every
// frame falls to exactly one rank and neighbouring frames, of similar cost, spread out.
std::vector<int> frames_for_rank(int count, int rank, int size);

// "00042": the stem of frame 42's files, padded so the files sort in frame order.
std::string frame_stem(int frame);

}  // namespace lenslab
