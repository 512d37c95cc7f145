// Closing every file descriptor from `first` up, in a forked child before exec (async-signal-safe). Its own
// file so that a platform without processes (the web page, src/web) builds a stand-in instead.
#pragma once

namespace raycam::check {

void close_descriptors_from(int first);

}  // namespace raycam::check
