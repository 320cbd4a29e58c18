# ITK 5.2 (Debian libinsighttoolkit5-dev): label images (NIfTI, NRRD, MetaImage) and their surfaces, used only by
# the hooke_image library (src/hooke/image). Its config runs FindHDF5, whose test compiles a C file: the project
# enables C for that alone. No ITK_USE_FILE: the image IO classes are chosen by extension, so no factory registration
# is generated and ITK's include directories stay on hooke_image.
find_package(ITK 5.2 REQUIRED COMPONENTS ITKCommon ITKIOImageBase ITKIONIFTI ITKIONRRD ITKIOMeta ITKMesh ITKSmoothing
                                         ITKThresholding)
# zlib (its library only: its include directory is /usr/include, which as -isystem breaks <cmath>): the check that
# a NIfTI file holds all its voxels.
find_package(ZLIB REQUIRED)
