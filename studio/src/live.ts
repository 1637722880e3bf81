// The live session's WebSocket: typed sends, every received message checked against the
// protocol's schema before the rest of the Studio sees it.
import { checkMessage } from './protocol/check';
import type { ClientMessage, ServerMessage } from './protocol/schema';

export type Listener = (m: ServerMessage) => void;

export class Live {
  private ws: WebSocket | null = null;
  private listeners: Listener[] = [];
  onStatus: (text: string) => void = () => {};

  connect(): void {
    const ws = new WebSocket(`ws://${location.host}/live`);
    this.ws = ws;
    ws.onopen = () => this.onStatus('connected');
    ws.onclose = () => this.onStatus('disconnected: reload the page to reconnect');
    ws.onmessage = (e) => {
      let m: unknown;
      try {
        m = JSON.parse(String(e.data));
      } catch {
        this.onStatus('the server sent a message that is not JSON');
        return;
      }
      const problem = checkMessage('server', m);
      if (problem) {
        this.onStatus(`the server sent a malformed message: ${problem}`);
        return;
      }
      for (const l of this.listeners) l(m as ServerMessage);
    };
  }

  on(l: Listener): void {
    this.listeners.push(l);
  }

  send(m: ClientMessage): void {
    if (this.ws?.readyState === WebSocket.OPEN) this.ws.send(JSON.stringify(m));
  }
}
