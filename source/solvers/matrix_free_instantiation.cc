// deal.II's MatrixFree for the SIMD width wetbed is compiled with
// (doc/developer_guide.md, "SIMD width"): the library holds these classes only for the
// width it was configured with (one lane in Debian's build); FEEvaluation and
// FEFaceEvaluation, templates on the degree, are compiled inline in the operator. Nothing
// is instantiated here when the two widths agree.
#include <deal.II/base/config.h>

#if defined(WETBED_LIBRARY_VECTORIZATION_WIDTH_IN_BITS) &&                               \
    DEAL_II_VECTORIZATION_WIDTH_IN_BITS != WETBED_LIBRARY_VECTORIZATION_WIDTH_IN_BITS
// the mapping's evaluation inside MatrixFree (MappingQ of degree 2) needs the
// runtime-degree evaluators: compiled for degrees 1 and 2 here, higher ones take
// deal.II's generic path
#define FE_EVAL_FACTORY_DEGREE_MAX 2
#include <deal.II/matrix_free/evaluation_template_face_factory.templates.h>
// (deal.II 9.4's two factory files share one include guard)
#undef dealii_matrix_free_evaluation_template_factory_templates_h
#include <deal.II/matrix_free/evaluation_template_factory.templates.h>
#include <deal.II/matrix_free/evaluation_template_factory_hanging_nodes.templates.h>
#include <deal.II/matrix_free/mapping_info.templates.h>
#include <deal.II/matrix_free/matrix_free.templates.h>
#include <deal.II/matrix_free/shape_info.templates.h>

namespace dealii
{
using WetbedVectorizedArray = VectorizedArray<double>;

#define WETBED_INSTANTIATE_MATRIX_FREE(dim)                                              \
  template class MatrixFree<dim, double, WetbedVectorizedArray>;                         \
  template void                                                                          \
  MatrixFree<dim, double, WetbedVectorizedArray>::internal_reinit<double, dim> (         \
      const std::shared_ptr<hp::MappingCollection<dim>> &,                               \
      const std::vector<const DoFHandler<dim, dim> *> &,                                 \
      const std::vector<const AffineConstraints<double> *> &,                            \
      const std::vector<IndexSet> &,                                                     \
      const std::vector<hp::QCollection<dim>> &,                                         \
      const MatrixFree<dim, double, WetbedVectorizedArray>::AdditionalData &);           \
  template struct internal::MatrixFreeFunctions::                                        \
      MappingInfo<dim, double, WetbedVectorizedArray>;                                   \
  template void internal::FEEvaluationFactory<dim, WetbedVectorizedArray>::evaluate (    \
      const unsigned int,                                                                \
      const EvaluationFlags::EvaluationFlags,                                            \
      const WetbedVectorizedArray *,                                                     \
      FEEvaluationData<dim, WetbedVectorizedArray, false> &);                            \
  template void                                                                          \
  internal::FEFaceEvaluationFactory<dim, WetbedVectorizedArray>::evaluate (              \
      const unsigned int,                                                                \
      const EvaluationFlags::EvaluationFlags,                                            \
      const WetbedVectorizedArray *,                                                     \
      FEEvaluationData<dim, WetbedVectorizedArray, true> &);                             \
  template struct internal::                                                             \
      FEEvaluationHangingNodesFactory<dim, double, WetbedVectorizedArray>;               \
  template void internal::MatrixFreeFunctions::ShapeInfo<                                \
      WetbedVectorizedArray>::reinit<dim, dim, dim> (const Quadrature<dim> &,            \
                                                     const FiniteElement<dim, dim> &,    \
                                                     unsigned int);

template struct internal::MatrixFreeFunctions::ShapeInfo<WetbedVectorizedArray>;
WETBED_INSTANTIATE_MATRIX_FREE (2)
WETBED_INSTANTIATE_MATRIX_FREE (3)
#undef WETBED_INSTANTIATE_MATRIX_FREE
} // namespace dealii
#endif
