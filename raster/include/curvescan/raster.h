// The core of curvescan in one include: paths, stroking and dashing, the rasterizer, paints and
// compositing, Canvas, Image and PNG I/O (library curvescan::raster, pkg-config curvescan-raster).
#pragma once

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/file_io.h"
#include "curvescan/raster/gradient.h"
#include "curvescan/raster/image.h"
#include "curvescan/raster/image_pattern.h"
#include "curvescan/raster/layer.h"
#include "curvescan/raster/limits.h"
#include "curvescan/raster/mask.h"
#include "curvescan/raster/paint.h"
#include "curvescan/raster/path.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/pixel_format.h"
#include "curvescan/raster/png_io.h"
#include "curvescan/raster/rasterizer.h"
#include "curvescan/raster/stroke.h"
#include "curvescan/raster/zeroed_memory.h"
#include "curvescan/status.h"
