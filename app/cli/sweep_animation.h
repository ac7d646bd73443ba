#pragma once
// A sweep's frames as one animation (`lenslab sweep --animation FILE`), made by ffmpeg run as
// a child process: lenslab links no video library.

#include <string>

namespace lenslab::cli {

// True for the names an animation may have: *.gif or *.mp4.
bool is_animation_path(const std::string& path);

// The ffmpeg to run: `program` when given (it must be an executable file), else ffmpeg on
// PATH. Throws Error saying how to get one when there is none.
std::string find_ffmpeg(const std::string& program);

// Encodes the first `count` of `frames` (a printf pattern such as DIR/frames/%05d.png,
// numbered from 0; a longer earlier sweep's may follow) at `fps` frames per second into
// `output` (GIF with its own palette, or H.264 MP4), atomically. Throws Error with ffmpeg's
// own words when it fails.
void assemble_animation(const std::string& ffmpeg, const std::string& frames, int count, int fps,
                        const std::string& output);

}  // namespace lenslab::cli
