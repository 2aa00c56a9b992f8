#include "eval/accuracy/scan_accuracy_run.h"

#include <sstream>

#include "eval/accuracy/name_map.h"
#include "eval/accuracy/reference_compare.h"
#include "eval/accuracy/reference_table.h"
#include "pipeline/batch/batch.h"
#include "pipeline/batch/batch_plan.h"
#include "pipeline/batch/batch_summary.h"
#include "pipeline/batch/done_record.h"
#include "scanners/core/atomic_file.h"
#include "scanners/core/errors.h"
#include "scanners/core/units.h"

namespace bespoke {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

bool SameFile(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  return !b.empty() && fs::equivalent(a, b, ec);
}

// The scans of the folder matched to the table's subjects; InputError when
// no subject has one. The table and the name map are never taken as scans.
ScanMatch FindScans(const ScanAccuracyOptions& options, const ReferenceTable& table) {
  std::vector<ScanEntry> scans;
  for (ScanEntry& e : DiscoverScans({}, options.scans_dir)) {
    if (!SameFile(e.path, options.reference) && !SameFile(e.path, options.names))
      scans.push_back(std::move(e));
  }
  ScanMatch match = MatchScans(table.subjects, scans);
  if (match.scans.empty()) {
    throw InputError(options.scans_dir,
                     "no scan belongs to a subject of " + options.reference.string() + " (" +
                         std::to_string(table.subjects.size()) + " subjects with values, " +
                         std::to_string(scans.size()) +
                         " scans; a subject's scans are SUBJECT.<ext> or SUBJECT_<k>.<ext>)");
  }
  return match;
}

// The batch's manifest of the matched scans, written into `dir`.
fs::path WriteManifest(const ScanMatch& match, const fs::path& dir) {
  std::ostringstream out;
  out << "id,path\n";
  for (const SubjectScan& s : match.scans)
    out << CsvField(s.scan.id) << ',' << CsvField(s.scan.path.string()) << '\n';
  const fs::path manifest = dir / "manifest.csv";
  WriteFileAtomically(manifest, out.str());
  return manifest;
}

BatchOptions BatchSettings(const ScanAccuracyOptions& options, const fs::path& manifest) {
  BatchOptions batch;
  batch.input = manifest;
  batch.out_dir = options.report_dir / "scans";
  batch.jobs = options.jobs;
  batch.units = options.units;
  batch.resume = options.resume;
  batch.retry_failed = options.retry_failed;
  batch.timeout_s = options.timeout_s;
  batch.memory_mb = options.memory_mb;
  batch.worker = options.worker;
  batch.label = "bespoke accuracy";
  return batch;
}

std::vector<ScanMeasurement> ReadScanResults(const ScanMatch& match, const fs::path& dir) {
  std::vector<ScanEntry> plan;
  for (const SubjectScan& s : match.scans) plan.push_back(s.scan);
  // The batch has just checked every folder's hashes.
  const std::vector<ScanOutcome> outcomes = CollectOutcomes(plan, dir, /*verify_hashes=*/false);
  std::vector<ScanMeasurement> results;
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const ScanOutcome& o = outcomes[i];
    results.push_back({match.scans[i].subject, o.entry.path.filename().string(),
                       o.ok() ? o.measurements : json(), o.failure_kind(), o.failure_message()});
  }
  return results;
}

json Settings(const ScanAccuracyOptions& o, const ReferenceTable& table) {
  return {{"command", "bespoke accuracy"},
          {"scans", o.scans_dir.string()},
          {"reference", o.reference.string()},
          {"names", o.names},
          {"method", table.method},
          {"jobs", o.jobs},
          {"units", o.units},
          {"resume", o.resume},
          {"retry_failed", o.retry_failed},
          {"timeout_s", o.timeout_s},
          {"memory_mb", o.memory_mb},
          {"scan_results", "scans/"},
          {"versions", BuildVersions()}};
}

}  // namespace

void ScanAccuracyOptions::Check() const {
  if (scans_dir.empty()) throw InputError("--scans: no folder of scans given");
  if (reference.empty()) throw InputError("--scans needs --reference REF.csv");
  if (report_dir.empty()) throw InputError("no report folder (-o REPORT)");
  std::error_code ec;
  if (!fs::is_directory(scans_dir, ec)) throw InputError(scans_dir, "--scans: not a folder");
  if (jobs < 0) throw InputError("--jobs must be >= 0 (0 = all CPUs)");
  if (timeout_s < 0) throw InputError("--timeout-s must be >= 0 (0 = no limit)");
  if (memory_mb < 0) throw InputError("--memory-mb must be >= 0 (0 = no limit)");
  if (retry_failed && !resume) throw InputError("--retry-failed needs --resume");
  if (!units.empty() && !ParseLengthUnit(units))
    throw InputError("--units '" + units + "': expected mm, cm, dm or m");
  if (!resume && fs::exists(report_dir / "scans" / kPlanFileName, ec)) {
    throw InputError(report_dir,
                     "already holds measured scans (scans/); pass --resume to "
                     "continue that run, or choose another report folder");
  }
}

ScanAccuracyOutcome RunScanAccuracy(const ScanAccuracyOptions& options, Progress* progress) {
  options.Check();
  const Catalogue& catalogue = Catalogue::Builtin();
  NameMap names;
  ReferenceTableOptions table_options;
  if (!options.names.empty()) {
    names = LoadNameMap(options.names, catalogue);
    table_options.names = &names;
  }
  table_options.method = options.method;
  const ReferenceTable table = ReadReferenceTable(table_options, options.reference, catalogue);
  const ScanMatch match = FindScans(options, table);
  ScanAccuracyOutcome outcome;
  outcome.scans = static_cast<int>(match.scans.size());
  const fs::path batch_dir = options.report_dir / "scans";
  CreateDirectories(batch_dir);
  const BatchOutcome batch =
      RunBatch(BatchSettings(options, WriteManifest(match, batch_dir)), progress);
  if (batch.interrupted) {
    outcome.interrupted = true;
    outcome.signal = batch.signal;
    return outcome;
  }
  outcome.report = CompareWithReference(table, ReadScanResults(match, batch_dir), catalogue);
  AccuracyReport& report = outcome.report;
  report.not_compared.insert(report.not_compared.end(), match.not_compared.begin(),
                             match.not_compared.end());
  report.created_utc = UtcNow();
  report.settings = Settings(options, table);
  report.title = "Bespoke accuracy report: " + std::to_string(table.subjects.size()) +
                 " subjects' scans against " + options.reference.filename().string() +
                 (table.method.empty() ? "" : " (" + table.method + ")");
  return outcome;
}

}  // namespace bespoke
