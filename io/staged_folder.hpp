#pragma once
// An output folder that appears whole or not at all: written as "DIR.partial" and put in
// place by commit(), after every file in it and the folder itself are on the disk. Over an
// existing DIR the new folder takes its place in one atomic exchange (renameat2 with
// RENAME_EXCHANGE; on a file system without it, two renames with the old folder kept as
// "DIR.replaced" until the new one is in place), so DIR never holds old and new files mixed.
// Entries of the old DIR that are not `owned` (a user's notes, a video they made) are
// carried into the new one, after each is checked to be movable (on the same file system;
// a folder writable): an entry that is not refuses the folder at construction and at commit,
// with nothing moved. Destroyed without commit, the staging folder is removed. A DIR that is
// a symbolic link stays one: the folder it points to is the one replaced. A DIR that is a
// mount point is refused at construction.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace covsim {

class StagedFolder {
 public:
  // `owned(name)`: whether an entry of an existing DIR is output of this kind of folder,
  // which the new folder replaces (and so does not carry over).
  StagedFolder(std::filesystem::path dir, std::function<bool(const std::string&)> owned);
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;
  ~StagedFolder();

  // Where to write: the staging folder.
  const std::filesystem::path& path() const { return staging_; }
  const std::filesystem::path& destination() const { return dir_; }
  // Syncs and puts the folder in place; throws std::runtime_error naming the folder.
  void commit();

 private:
  // The entries of an existing DIR to carry over, each checked to be movable; throws
  // std::invalid_argument naming the first that is not, before anything moves.
  std::vector<std::string> entries_to_carry() const;

  std::filesystem::path dir_, staging_, replaced_;
  std::function<bool(const std::string&)> owned_;
  bool committed_ = false;
  bool stranded_ = false;
};

}  // namespace covsim
