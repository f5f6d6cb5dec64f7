// What work_precision prints and writes: every row, the CSV for the plot, and the summaries (the
// goal against each peer, run by run; the key figures at the usual settings) as text and Markdown.
#pragma once
#include <string>
#include <vector>

#include "runs.h"

namespace platon::bench::precision {

void printRow(const Row& r);
void writeCsv(const std::vector<Row>& rows, const std::string& path);

// The summaries; `titles` are the scenes' one-line descriptions, by name, in report order.
struct Titles {
  std::vector<std::string> names, lines;
};
std::string summaryMarkdown(const std::vector<Row>& rows, const Titles& titles, int runs);

}  // namespace platon::bench::precision
