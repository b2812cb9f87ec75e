// Bundles src/main.js and what it imports (uPlot, three.js, the CSS as text) into one minified
// IIFE, dist/report.js, which CMake embeds in the yardsim binary. Deterministic: CI rebuilds it
// with the pinned packages and fails if it differs from the committed one.
import { build } from 'esbuild';

await build({
  entryPoints: ['src/main.js'],
  bundle: true,
  minify: true,
  format: 'iife',
  target: 'es2020',
  loader: { '.css': 'text' },
  legalComments: 'eof',
  banner: { js: '/*! yardsim report bundle (report/ in the yardsim sources). Includes uPlot 1.6.32, Copyright (c) 2025 Leon Sorokin, MIT License; three.js 0.187.0, Copyright 2010-2026 Three.js Authors, MIT License. */' },
  outfile: 'dist/report.js',
  logLevel: 'info',
});
