#include "poroseam/elastic.hpp"

namespace poroseam::physics {

ElasticModuli lameFromYoung(double young, double poisson)
{
  ElasticModuli m;
  m.shear = young / (2.0 * (1.0 + poisson));
  m.lambda = young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
  return m;
}

void elasticStress(const ElasticModuli &m, const double strain[3][3], double stress[3][3])
{
  const double trace = strain[0][0] + strain[1][1] + strain[2][2];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      stress[i][j] = 2.0 * m.shear * strain[i][j] + (i == j ? m.lambda * trace : 0.0);
}

double elasticTangent(const ElasticModuli &m, int i, int j, int k, int l)
{
  const double dij = i == j, dkl = k == l, dik = i == k, djl = j == l, dil = i == l, djk = j == k;
  return m.lambda * dij * dkl + m.shear * (dik * djl + dil * djk);
}

} // namespace poroseam::physics
