// Merging the results files of a sweep's shards (`curvebench sweep --shard i/n`, one per task
// of a Slurm job array) back into the results of the whole sweep.
//
// In:  the plan (sweep_plan.h) and the shard files' paths (any order, any number).
// Out: the text of the merged results file: every planned run's row exactly once, in plan
//      order, each line as its shard wrote it, so the merge of the shards of a sweep equals the
//      sweep run on one machine apart from the measurements at the end of each row.
// Throws std::runtime_error if a line is not a sweep row (naming the file and the line), or if
// a planned run has no row, a run has more than one row, or a row is of no planned run: the
// message counts each kind and names the first runs of it (plan index, algorithm, input).
#pragma once

#include <string>
#include <vector>

#include "sweep/sweep_plan.h"

namespace curvebench {

std::string merge_shards(const SweepPlan& plan, const std::vector<std::string>& shard_paths);

}  // namespace curvebench
