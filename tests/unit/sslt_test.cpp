// POV-Ray's subsurface light transport terms (render/materials/sslt.h) against their own
// definitions: the dipole's R_d(r) integrated over the plane is the total diffuse reflectance
// POV-Ray inverts for the reduced albedo, the inversion round-trips, and the Fresnel
// transmittance meets its closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "render/materials/sslt.h"

namespace glint::render {
namespace {

TEST(Sslt, FresnelTransmittanceAtNormalIncidenceAndIndexMatched) {
    // 1 - ((eta - 1) / (eta + 1))^2 head-on; no interface at eta = 1.
    EXPECT_NEAR(sslt_transmittance(1.0, 1.5), 1 - 0.04, 1e-12);
    EXPECT_NEAR(sslt_transmittance(1.0, 1.33), 1 - std::pow(0.33 / 2.33, 2), 1e-12);
    EXPECT_NEAR(sslt_transmittance(0.3, 1.0), 1.0, 1e-12);
    // Less gets through at grazing angles, none past the critical angle going out.
    EXPECT_LT(sslt_transmittance(0.1, 1.5), sslt_transmittance(0.9, 1.5));
    EXPECT_EQ(sslt_transmittance(0.2, 1 / 1.5), 0.0);
}

TEST(Sslt, ReducedAlbedoInvertsTheTotalReflectance) {
    for (double eta : {1.3, 1.45, 2.0}) {
        const double fdr = fresnel_diffuse_reflectance(eta);
        const double A = (1 + fdr) / (1 - fdr);
        for (double r : {0.02, 0.2, 0.5, 0.8, 0.97}) {
            const double alpha = reduced_albedo(r, eta);
            EXPECT_NEAR(dipole_total_reflectance(A, alpha), r, 1e-9) << eta << " " << r;
        }
    }
    EXPECT_EQ(reduced_albedo(0, 1.5), 0);
    EXPECT_EQ(reduced_albedo(1.2, 1.5), 1);  // clamped
}

TEST(Sslt, DipoleIntegratesToTheTotalDiffuseReflectance) {
    // Jensen et al.'s R_d(r) over the plane, 2 pi r dr, is the closed-form total R_d: the
    // diffuse term of a flat, uniformly lit surface returns pigment times diffuse.
    for (double eta : {1.3, 1.5}) {
        for (double albedo : {0.3, 0.8, 0.99}) {
            const double sigma_prime_s = 2.0;  // per mm
            const double sigma_t = sigma_prime_s / albedo, sigma_a = sigma_t - sigma_prime_s;
            // r = x^3 (dense near 0, where R_d peaks), midpoint rule in x out to 20 mm.
            const int n = 400000;
            const double x_max = std::cbrt(20.0);
            double sum = 0;
            for (int i = 0; i < n; ++i) {
                const double x = (i + 0.5) / n * x_max, r = x * x * x;
                sum += 2 * kPi * r * dipole_reflectance(r * r, sigma_prime_s, sigma_a, eta) *
                       3 * x * x * (x_max / n);
            }
            const double fdr = fresnel_diffuse_reflectance(eta);
            const double exact = dipole_total_reflectance((1 + fdr) / (1 - fdr), albedo);
            std::printf("eta %.2f albedo %.2f: integral %.6f, closed form %.6f\n", eta, albedo,
                        sum, exact);
            EXPECT_NEAR(sum, exact, 1e-4 * (1 + exact));
        }
    }
}

TEST(Sslt, CoefficientsFromTranslucencyAndColour) {
    const SsltCoefficients k(Color(2, 1, 0.5), Color(0.6, 0.3, 0.05), 1.45);
    EXPECT_DOUBLE_EQ(k.sigma_prime_s.r, 0.5);
    EXPECT_DOUBLE_EQ(k.sigma_prime_s.b, 2.0);
    // Extinction is scattering over the reduced albedo; absorption what is left.
    EXPECT_NEAR(k.sigma_prime_s.g / k.sigma_prime_t.g, reduced_albedo(0.3, 1.45), 1e-12);
    EXPECT_NEAR(k.sigma_a.g, k.sigma_prime_t.g - k.sigma_prime_s.g, 1e-12);
    EXPECT_GT(k.sigma_a.b, k.sigma_a.r);  // a darker channel absorbs more
}

}  // namespace
}  // namespace glint::render
