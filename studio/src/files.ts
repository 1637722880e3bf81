// The workspace's files over plain HTTP (POST /api/CALL with a JSON body).
export async function api<T = Record<string, unknown>>(call: string, body: object): Promise<T> {
  const res = await fetch(`/api/${call}`, {
    method: 'POST',
    headers: { 'Content-Type': 'application/json' },
    body: JSON.stringify(body),
  });
  const data = (await res.json()) as T & { error?: string };
  if (!res.ok) throw new Error(data.error ?? `${call} failed (${res.status})`);
  return data;
}
