#include <wetbed/postprocess/csv_append.h>

#include <filesystem>
#include <stdexcept>

namespace wetbed
{
void continue_csv (std::ofstream           &file,
                   const std::string       &filename,
                   const unsigned long long bytes)
{
  std::error_code error;
  const auto      size = std::filesystem::file_size (filename, error);
  if (error || size < bytes)
    throw std::runtime_error ("checkpoint/resume: " + filename +
                              " is shorter than when the checkpoint was written");
  std::filesystem::resize_file (filename, bytes);
  file.open (filename, std::ios::app);
}
} // namespace wetbed
