// What a sandboxed program is shown besides the system: its own folder and the folders of the files its
// command names. Such a folder must never hold more than the student brought: not /, not the invoking user's
// home as a whole, not a folder holding the checker's outputs or (in a batch) the other students' folders.
#pragma once

#include <string>
#include <vector>

namespace raycam::check {

// The folders of the absolute paths in `argv` naming an existing file (its folder) or folder (itself), outside
// /usr (shown anyway).
std::vector<std::string> folders_named(const std::vector<std::string>& argv);

// Throws std::invalid_argument naming `flag` when a folder of `shown` is /, the home folder `home` or one
// above it, or holds one of `protected_paths` (outputs, a batch's folder) at any depth; the message says to
// give the program a folder of its own.
void refuse_exposed_folders(const std::vector<std::string>& shown, const std::string& home,
                            const std::vector<std::string>& protected_paths, const std::string& flag);

// Why one submission of a batch is not run, or "" when it can be: its folder (`folder`, an entry of the
// batch's folder `root`) is a symbolic link or its real path leaves `root`; a word of its command naming a
// path inside the folder leads out of it through a link, or names a folder where a file is expected. The
// refusal is that row's, in words an instructor can act on; the rest of the class is graded.
std::string submission_refusal(const std::string& folder, const std::string& root, const std::vector<std::string>& argv);

// Why a sandboxed run by root could not read `folder` (root's runs have no more rights than any user: the
// folder and those above it must be crossable by others, the folder readable), or "" when it can.
std::string unreadable_by_others(const std::string& folder);

// A hint for a program that could not start, from the files its command names: a script with Windows line
// ends ("#!/usr/bin/python3\r" names no interpreter) or a program without its run bit. "" when none applies.
std::string launch_hint(const std::vector<std::string>& argv);

}  // namespace raycam::check
