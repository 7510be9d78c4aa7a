// What a static analysis reports per member of a frame (Model::members): a CSV table along
// each member in member axes, and in results.json each resultant's exact largest and
// smallest value with its place, the member's deflection from its chord, and the largest
// displacement of the whole structure (fem/assembly/MemberExtrema.hpp).
#pragma once

#include <string>
#include <vector>

#include "fem/assembly/MemberEnvelope.hpp"
#include "fem/model/Model.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/output/structure/LineSampling.hpp"
#include "problems/output/structure/StaticExtremes.hpp"

namespace beamrotor {

/// `<stem>_member_<name>.csv`.
std::string memberCsv(const std::string& stem, const std::string& member);
/// `<stem>_members.csv`: every member's rows in one table (oneMembersTable).
std::string membersCsv(const std::string& stem);

/// A frame of more members than this writes one table of them all (membersCsv) in place of a
/// file per member (memberCsv): thousands of files help no reader, and one table loads into a
/// spreadsheet or pandas at once.
inline constexpr std::size_t kMemberFilesUpTo = 100;
/// Whether the model's members go into one table (more than kMemberFilesUpTo of them).
bool oneMembersTable(const Model& model);
/// The CSV file that holds member `member`'s rows: its own, or the one members table.
std::string memberCsvOf(const Model& model, const std::string& stem, const std::string& member);

/// One row per station of the member's elements (from `stations`, sampleStatics), in order
/// from its start: s (m from its start), x y z (m, global place), ux uy uz (m), rx ry rz (rad,
/// global), N Vy Vz (N), T My Mz (N m) in member axes, stress (Pa), element, and the member's
/// local y and z axes in global components (ey_x .. ez_z; the charts draw diagrams along them).
/// Each member's rows cost their own number: the stations are found by element.
CsvTable memberTable(const std::string& title, const Model& model,
                     const std::vector<int>& elements, const StationsByElement& stations);

/// Every member's rows as memberTable gives them, in the model's member order, each row led
/// by a `member` column with the member's name.
CsvTable membersTable(const std::string& title, const Model& model,
                      const StationsByElement& stations);

/// `<stem>_envelope_<name>.csv`.
std::string envelopeCsv(const std::string& stem, const std::string& member);
/// `<stem>_envelopes.csv`: every member's envelope in one table (oneMembersTable).
std::string envelopesCsv(const std::string& stem);
/// The CSV file that holds member `member`'s envelope: its own, or the one envelopes table.
std::string envelopeCsvOf(const Model& model, const std::string& stem, const std::string& member);

/// Whether results.json and the cases CSV give each load case's and combination's member
/// extremes: while members times cases stay within kCaseMemberEntries. Beyond, each case keeps
/// its reactions, point displacements, largest displacement and stresses, and the envelope
/// gives every member's extremes over the combinations with the one that governs each.
inline constexpr std::size_t kCaseMemberEntries = 20000;
bool caseMemberDetail(const Model& model, std::size_t cases);

/// Load cases and combinations the summary gives in full at most (member extremes and chord
/// deflections included); more get a line each.
inline constexpr std::size_t kSummaryCases = 12;

/// Whether each case's and combination's chord deflections are reported (results.json's
/// member detail, caseMemberDetail, or the summary's cases in full); when they are not, they
/// are not computed.
bool caseChordDeflections(const Model& model, std::size_t cases);

/// The envelope over the combinations along one member (memberEnvelope), one row per place:
/// s (m from its start), element, then for each of N Vy Vz T My Mz its largest value, the
/// combination giving it, its smallest value and the combination giving that.
CsvTable memberEnvelopeTable(const std::string& title, const std::vector<EnvelopeStation>& stations,
                             const std::vector<std::string>& solutionNames);

/// Every member's envelope (memberEnvelope of each, Model::members() order) in one table, each
/// row led by a `member` column.
CsvTable membersEnvelopeTable(const std::string& title, const Model& model,
                              const std::vector<std::vector<EnvelopeStation>>& stations,
                              const std::vector<std::string>& solutionNames);

/// {"NAME": {"length", "elements", "from", "to", "N": {"max": {value, s, x, y, z, element},
/// "min": {...}}, ... "Mz": ..., "chord_deflection": {value, s, x, y, z, element}, "csv"}}; "csv"
/// names memberCsvOf.
Json membersJson(const Model& model, const StaticExtremes& extremes, const std::string& stem);

/// {value, x, y, z}: the largest translation anywhere and where (undeformed place).
Json maxDisplacementJson(const MemberValue& top);

}  // namespace beamrotor
