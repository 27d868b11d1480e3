#!/bin/sh
# The upright settling box of bench/mixture_box.c as a driftFluxFoam case
# (OpenFOAM, Debian package openfoam: a comparison, not a dependency):
# 0.1 m x 1 m, 4 x N hexahedra one cell deep (front and back empty), walls
# all round, alpha = 0.1 of 1006 kg/m3 particles in 996 kg/m3 water
# (viscosity 1e-3 Pa s: the "plastic" mixture viscosity with a zero
# coefficient), the "simple" relative velocity V0 10^(-A alpha) with V0 =
# 2.198 mm/s, bounded at ALPHA_MAX (the step cut-off of sluice's vesilind
# closure), fixed steps DT, the alpha equation sub-cycled SUB times a step,
# written at T_END only.
#   box_case.sh DIR N DT SUB T_END A ALPHA_MAX
set -e
dir=$1 n=$2 dt=$3 sub=$4 tend=$5 a=$6 amax=$7
mkdir -p "$dir/system" "$dir/constant" "$dir/0"
head() {
  printf 'FoamFile\n{\n    version 2.0;\n    format ascii;\n    class %s;\n    object %s;\n}\n' "$1" "$2"
}
{ head dictionary blockMeshDict
  cat <<BLOCK
convertToMeters 1;
vertices ((0 0 0) (0.1 0 0) (0.1 1 0) (0 1 0) (0 0 0.01) (0.1 0 0.01) (0.1 1 0.01) (0 1 0.01));
blocks (hex (0 1 2 3 4 5 6 7) (4 $n 1) simpleGrading (1 1 1));
edges ();
boundary
(
    walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
mergePatchPairs ();
BLOCK
} > "$dir/system/blockMeshDict"
{ head dictionary controlDict
  cat <<CTRL
application driftFluxFoam;
startFrom startTime;
startTime 0;
stopAt endTime;
endTime $tend;
deltaT $dt;
writeControl runTime;
writeInterval $tend;
purgeWrite 0;
writeFormat ascii;
writePrecision 12;
writeCompression off;
timeFormat general;
timePrecision 8;
runTimeModifiable false;
adjustTimeStep no;
CTRL
} > "$dir/system/controlDict"
{ head dictionary fvSchemes
  cat <<SCHEMES
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes
{
    default none;
    div(rhoPhi,U) Gauss linearUpwind grad(U);
    div(phi,alpha) Gauss vanLeer;
    div(phirb,alpha) Gauss linear;
    div(tauDm) Gauss linear;
    div(((rho*nuEff)*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
SCHEMES
} > "$dir/system/fvSchemes"
{ head dictionary fvSolution
  cat <<SOLVE
solvers
{
    "alpha.sludge.*" { nAlphaCorr 1; nAlphaSubCycles $sub; MULESCorr no; }
    alpha1Diffusion { solver PBiCGStab; preconditioner DILU; tolerance 1e-12; relTol 0; }
    p_rgh { solver PCG; preconditioner DIC; tolerance 1e-10; relTol 0.01; }
    p_rghFinal { \$p_rgh; relTol 0; }
    "(U|UFinal)" { solver PBiCGStab; preconditioner DILU; tolerance 1e-10; relTol 0; }
}
PIMPLE { momentumPredictor no; nOuterCorrectors 1; nCorrectors 2; nNonOrthogonalCorrectors 0; pRefCell 0; pRefValue 0; }
SOLVE
} > "$dir/system/fvSolution"
{ head uniformDimensionedVectorField g
  printf 'dimensions [0 1 -2 0 0 0 0];\nvalue (0 -9.81 0);\n'
} > "$dir/constant/g"
{ head dictionary turbulenceProperties
  printf 'simulationType laminar;\n'
} > "$dir/constant/turbulenceProperties"
{ head dictionary transportProperties
  cat <<TRANS
phases (sludge water);
sludge
{
    transportModel plastic;
    plasticCoeffs { coeff 0; exponent 0; muMax 10; }
    rho 1006;
    alphaMax $amax;
}
water { transportModel Newtonian; nu 1.00401606e-06; rho 996; }
alphaMax $amax;
relativeVelocityModel simple;
simpleCoeffs { V0 (0 -0.002198 0); a $a; residualAlpha 0; }
TRANS
} > "$dir/constant/transportProperties"
{ head volScalarField alpha.sludge
  printf 'dimensions [0 0 0 0 0 0 0];\ninternalField uniform 0.1;\n'
  printf 'boundaryField\n{\n    walls { type zeroGradient; }\n    frontAndBack { type empty; }\n}\n'
} > "$dir/0/alpha.sludge"
{ head volVectorField U
  printf 'dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n'
  printf 'boundaryField\n{\n    walls { type noSlip; }\n    frontAndBack { type empty; }\n}\n'
} > "$dir/0/U"
{ head volScalarField p_rgh
  printf 'dimensions [1 -1 -2 0 0 0 0];\ninternalField uniform 0;\n'
  printf 'boundaryField\n{\n    walls { type fixedFluxPressure; value uniform 0; }\n    frontAndBack { type empty; }\n}\n'
} > "$dir/0/p_rgh"
{ head volScalarField p
  printf 'dimensions [1 -1 -2 0 0 0 0];\ninternalField uniform 0;\n'
  printf 'boundaryField\n{\n    walls { type calculated; value uniform 0; }\n    frontAndBack { type empty; }\n}\n'
} > "$dir/0/p"
