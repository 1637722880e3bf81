// Vite builds the Studio's front end into the folder that the feel build embeds
// (src/studio/CMakeLists.txt passes --outDir). The protocol's schema (src/protocol/schema.ts)
// is also written as protocol.json there, for the C++ server to check messages against.
import { defineConfig } from 'vite';
import { schema } from './src/protocol/schema.ts';

export default defineConfig({
  base: '/',
  build: { target: 'es2022', sourcemap: false, chunkSizeWarningLimit: 2000 },
  plugins: [
    {
      name: 'feel-protocol-json',
      generateBundle() {
        this.emitFile({ type: 'asset', fileName: 'protocol.json', source: JSON.stringify(schema, null, 1) });
      },
    },
  ],
});
