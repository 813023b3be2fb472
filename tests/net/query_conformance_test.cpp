// The Model Checking Contest's 2021 formulas on the conformance nets against the contest's
// reference answers (tests/data/conformance/queries, oracle.tsv): every formula of all seven
// categories must be answered, and answered as the oracle says (the LTL categories of the two
// largest nets left out for their time).

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "gdpn/core/file.h"
#include "gdpn/net/query.h"
#include "support/conformance.h"

namespace gdpn::net {
namespace {

using testing::conformanceNet;
using testing::kConformanceDir;

std::map<std::string, std::string> oracle() {
  std::map<std::string, std::string> out;
  std::ifstream in(kConformanceDir / "queries" / "oracle.tsv");
  std::string id, answer;
  while (in >> id >> answer) out[id] = answer;
  return out;
}

std::string word(const QueryAnswer& a) {
  switch (a.verdict) {
    case Verdict::True: return "TRUE";
    case Verdict::False: return "FALSE";
    case Verdict::Value: return std::to_string(a.value);
    case Verdict::Unknown: break;
  }
  return "UNKNOWN";
}

class ContestFormulas : public ::testing::TestWithParam<const char*> {};

TEST_P(ContestFormulas, EveryAnswerIsTheOracles) {
  const std::string model = GetParam();
  const auto net = conformanceNet(model);
  ASSERT_TRUE(net);
  const auto expected = oracle();
  ASSERT_EQ(expected.size(), 1568u);
  std::vector<Property> asked;
  std::vector<bool> ltl;  // per formula: from an LTL category
  // the two nets of millions of markings: LTL's product with their graph takes minutes per
  // formula as yet (issue 19), so their LTL categories are left out here
  const bool big = model == "Kanban-PT-00005" || model == "SwimmingPool-PT-02";
  for (const char* category : {"ReachabilityCardinality", "ReachabilityFireability", "UpperBounds", "CTLCardinality",
                               "CTLFireability", "LTLCardinality", "LTLFireability"}) {
    if (big && std::string(category).starts_with("LTL")) continue;
    const auto file = (kConformanceDir / "queries" / model / (std::string(category) + ".xml")).string();
    core::Diagnostics diags;
    const auto text = core::readFile(file, diags);
    ASSERT_TRUE(text) << diags.str();
    auto properties = readMccProperties(*net, *text, file, diags);
    ASSERT_TRUE(properties) << diags.str();
    EXPECT_EQ(properties->size(), 16u) << category;
    asked.insert(asked.end(), properties->begin(), properties->end());
    ltl.resize(asked.size(), std::string(category).starts_with("LTL"));
  }
  // one batch: the graph is stored once for all of them
  std::vector<Formula> formulas;
  for (const auto& p : asked) formulas.push_back(p.formula);
  const auto answers = answerQueries(*net, formulas);
  for (std::size_t i = 0; i < asked.size(); ++i) {
    const auto at = expected.find(asked[i].id);
    ASSERT_NE(at, expected.end()) << asked[i].id;
    EXPECT_EQ(word(answers[i]), at->second)
        << asked[i].id << (ltl[i] ? " (LTL)" : "") << ": " << formulaText(*net, asked[i].formula) << " "
        << answers[i].unsupported;
  }
}

INSTANTIATE_TEST_SUITE_P(Nets, ContestFormulas,
                         ::testing::Values("ResAllocation-PT-R002C002", "ERK-PT-000001", "Eratosthenes-PT-010",
                                           "Angiogenesis-PT-01", "TokenRing-PT-005", "Philosophers-PT-000005",
                                           "CircularTrains-PT-012", "RobotManipulation-PT-00002", "FMS-PT-00002",
                                           "Dekker-PT-010", "Referendum-PT-0010", "Philosophers-PT-000010",
                                           "Kanban-PT-00005", "SwimmingPool-PT-02"),
                         [](const ::testing::TestParamInfo<const char*>& param) {
                           std::string name = param.param;
                           for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

}  // namespace
}  // namespace gdpn::net
