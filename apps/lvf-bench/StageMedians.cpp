#include "StageMedians.h"

#include <lvfusion/common/Medians.h>

#include <algorithm>
#include <iomanip>

namespace lvf::bench
{
void StageMedians::add(const std::string& method, const std::string& stage, double ms)
{
	if (!m_methods.count(method)) m_methodOrder.push_back(method);
	Method& m = m_methods[method];
	if (!m.perStage.count(stage)) m.stageOrder.push_back(stage);
	m.perStage[stage].push_back(ms);
}

double StageMedians::median(const std::string& method, const std::string& stage) const
{
	const auto m = m_methods.find(method);
	if (m == m_methods.end()) return 0;
	const auto s = m->second.perStage.find(stage);
	return s == m->second.perStage.end() ? 0 : lvf::common::median(s->second, 0);
}

double StageMedians::medianTotal(const std::string& method) const
{
	const auto m = m_methods.find(method);
	if (m == m_methods.end()) return 0;
	// Every stage is recorded once per frame, so index k is frame k.
	std::vector<double> totals;
	for (const auto& [stage, samples] : m->second.perStage)
	{
		totals.resize(std::max(totals.size(), samples.size()), 0.0);
		for (size_t k = 0; k < samples.size(); k++) totals[k] += samples[k];
	}
	return lvf::common::median(totals, 0);
}

void StageMedians::print(std::ostream& out, const std::string& baseline, const std::string& indent) const
{
	const double base = medianTotal(baseline);
	for (const auto& name : m_methodOrder)
	{
		const Method& m = m_methods.at(name);
		out << indent << std::setw(29) << std::left << name << std::right << std::fixed
			<< std::setprecision(2);
		for (const auto& stage : m.stageOrder) out << "  " << stage << " " << median(name, stage);
		const double total = medianTotal(name);
		out << "  | total " << total << " ms";
		if (total > 0 && base > 0) out << " (" << base / total << "x vs " << baseline << ")";
		out << "\n";
	}
}

}  // namespace lvf::bench
