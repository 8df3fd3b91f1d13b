#include "terrain/height_tile_cache.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace ig::terrain {
template <class T>
TileCache<T>::TileCache(int width, int height, int tile_size, std::size_t budget_bytes, Reader reader)
    : width_(width),
      height_(height),
      tile_(tile_size),
      tiles_x_(tile_size > 0 ? (width + tile_size - 1) / tile_size : 0),
      tiles_y_(tile_size > 0 ? (height + tile_size - 1) / tile_size : 0),
      budget_(budget_bytes),
      reader_(std::move(reader)) {
  if (width < 1 || height < 1 || tile_size < 1 || !reader_)
    throw std::invalid_argument("TileCache: needs a size, a tile size and a reader");
  loader_ = std::thread([this] { loader_loop(); });
}

template <class T>
TileCache<T>::~TileCache() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  loader_.join();
}

template <class T>
typename TileCache<T>::TilePtr TileCache<T>::load(int k) const {
  const int tx = k % tiles_x_, ty = k / tiles_x_;
  const int x0 = tx * tile_, y0 = ty * tile_;
  const int w = std::min(tile_, width_ - x0), h = std::min(tile_, height_ - y0);
  auto t = std::make_shared<Tile>(static_cast<std::size_t>(w) * h);
  std::lock_guard read_lock(read_mutex_);
  reader_(tx, ty, x0, y0, w, h, t->data());
  return t;
}

template <class T>
void TileCache<T>::insert_locked(int k, TilePtr t) const {
  lru_.push_front(k);
  stats_.resident_bytes += t->size() * sizeof(T);
  tiles_[k] = Entry{std::move(t), lru_.begin()};
  while (stats_.resident_bytes > budget_ && lru_.size() > 1) {
    const int victim = lru_.back();
    lru_.pop_back();
    auto it = tiles_.find(victim);
    stats_.resident_bytes -= it->second.tile->size() * sizeof(T);
    tiles_.erase(it);
    ++stats_.evictions;
  }
  stats_.resident_tiles = static_cast<int>(tiles_.size());
  stats_.peak_resident_bytes = std::max(stats_.peak_resident_bytes, stats_.resident_bytes);
}

template <class T>
typename TileCache<T>::TilePtr TileCache<T>::get(int k) const {
  std::unique_lock lock(mutex_);
  bool counted = false;
  for (;;) {
    if (auto it = tiles_.find(k); it != tiles_.end()) {
      lru_.splice(lru_.begin(), lru_, it->second.lru);
      return it->second.tile;
    }
    if (!counted) {
      ++stats_.misses;
      counted = true;
    }
    if (!loading_.count(k)) break;
    changed_.wait(lock);  // the background thread is reading it
  }
  loading_.insert(k);
  lock.unlock();
  TilePtr t;
  try {
    t = load(k);
  } catch (...) {
    lock.lock();
    loading_.erase(k);
    changed_.notify_all();
    throw;
  }
  lock.lock();
  loading_.erase(k);
  insert_locked(k, t);
  changed_.notify_all();
  return t;
}

template <class T>
typename TileCache<T>::TilePtr TileCache<T>::get_if_resident(int k) const {
  std::lock_guard lock(mutex_);
  if (auto it = tiles_.find(k); it != tiles_.end()) {
    lru_.splice(lru_.begin(), lru_, it->second.lru);
    return it->second.tile;
  }
  if (!loading_.count(k)) {  // next for the background thread
    queue_.erase(std::remove(queue_.begin(), queue_.end(), k), queue_.end());
    queue_.push_front(k);
    changed_.notify_all();
  }
  ++stats_.deferred;
  return nullptr;
}

template <class T>
std::optional<T> TileCache<T>::at_if_resident(int i, int j) const {
  const TilePtr t = get_if_resident(key(i / tile_, j / tile_));
  if (!t) return std::nullopt;
  const int x0 = (i / tile_) * tile_, y0 = (j / tile_) * tile_;
  const int w = std::min(tile_, width_ - x0);
  return (*t)[static_cast<std::size_t>(j - y0) * w + (i - x0)];
}

template <class T>
T TileCache<T>::at(int i, int j) const {
  const TilePtr t = get(key(i / tile_, j / tile_));
  const int x0 = (i / tile_) * tile_, y0 = (j / tile_) * tile_;
  const int w = std::min(tile_, width_ - x0);
  return (*t)[static_cast<std::size_t>(j - y0) * w + (i - x0)];
}

template <class T>
template <class Fetch>
void TileCache<T>::copy_rect(int x, int y, int w, int h, T* dst, std::size_t dst_stride, Fetch&& fetch) const {
  if (w <= 0 || h <= 0) return;
  for (int ty = y / tile_; ty <= (y + h - 1) / tile_; ++ty)
    for (int tx = x / tile_; tx <= (x + w - 1) / tile_; ++tx) {
      const TilePtr t = fetch(key(tx, ty));
      const int x0 = tx * tile_, y0 = ty * tile_;
      const int tw = std::min(tile_, width_ - x0);
      const int cx0 = std::max(x, x0), cx1 = std::min(x + w, x0 + tw);
      const int cy0 = std::max(y, y0), cy1 = std::min(y + h, y0 + std::min(tile_, height_ - y0));
      for (int r = cy0; r < cy1; ++r)
        std::memcpy(dst + static_cast<std::size_t>(r - y) * dst_stride + (cx0 - x),
                    t->data() + static_cast<std::size_t>(r - y0) * tw + (cx0 - x0),
                    static_cast<std::size_t>(cx1 - cx0) * sizeof(T));
    }
}

template <class T>
void TileCache<T>::read_rect(int x, int y, int w, int h, T* dst, std::size_t dst_stride) const {
  copy_rect(x, y, w, h, dst, dst_stride, [this](int k) { return get(k); });
}

template <class T>
int TileCache<T>::try_read_rect(int x, int y, int w, int h, T* dst, std::size_t dst_stride) const {
  if (w <= 0 || h <= 0) return 0;
  std::unordered_map<int, TilePtr> held;  // taken under the lock, so eviction cannot take them away
  int missing = 0;
  {
    std::lock_guard lock(mutex_);
    for (int ty = y / tile_; ty <= (y + h - 1) / tile_; ++ty)
      for (int tx = x / tile_; tx <= (x + w - 1) / tile_; ++tx) {
        const auto it = tiles_.find(key(tx, ty));
        if (it == tiles_.end()) {
          ++missing;
          continue;
        }
        lru_.splice(lru_.begin(), lru_, it->second.lru);
        held.emplace(key(tx, ty), it->second.tile);
      }
  }
  if (missing == 0) copy_rect(x, y, w, h, dst, dst_stride, [&held](int k) { return held.at(k); });
  return missing;
}

template <class T>
void TileCache<T>::request(int x, int y, int w, int h) const {
  const int tx0 = std::max(x, 0) / tile_, ty0 = std::max(y, 0) / tile_;
  const int tx1 = (std::min(x + w, width_) - 1) / tile_, ty1 = (std::min(y + h, height_) - 1) / tile_;
  if (tx1 < tx0 || ty1 < ty0 || x + w <= 0 || y + h <= 0) return;
  // Nearest the centre first; no more tiles than the budget holds.
  const double cx = 0.5 * (tx0 + tx1), cy = 0.5 * (ty0 + ty1);
  std::vector<std::pair<double, int>> order;
  for (int ty = ty0; ty <= ty1; ++ty)
    for (int tx = tx0; tx <= tx1; ++tx) order.emplace_back(std::hypot(tx - cx, ty - cy), key(tx, ty));
  std::sort(order.begin(), order.end());
  const std::size_t full_tile = static_cast<std::size_t>(tile_) * tile_ * sizeof(T);
  const std::size_t fit = std::max<std::size_t>(1, budget_ / full_tile);
  if (order.size() > fit) order.resize(fit);
  {
    std::lock_guard lock(mutex_);
    // Farthest first into the LRU front, so the nearest end up most recent.
    for (auto it = order.rbegin(); it != order.rend(); ++it)
      if (auto t = tiles_.find(it->second); t != tiles_.end()) lru_.splice(lru_.begin(), lru_, t->second.lru);
    std::deque<int> fresh;
    std::unordered_set<int> in_fresh;
    for (const auto& [d, k] : order)
      if (!tiles_.count(k) && !loading_.count(k) && in_fresh.insert(k).second) fresh.push_back(k);
    if (fresh.empty()) return;  // all resident or on their way: the queue stays as it is
    // The newest request first; older queued tiles after it, while they fit.
    for (int k : queue_)
      if (fresh.size() < fit && in_fresh.insert(k).second) fresh.push_back(k);
    queue_.swap(fresh);
  }
  changed_.notify_all();
}

template <class T>
void TileCache<T>::loader_loop() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [this] { return stop_ || !queue_.empty(); });
    if (stop_) return;
    const int k = queue_.front();
    queue_.pop_front();
    if (tiles_.count(k) || loading_.count(k)) continue;
    loading_.insert(k);
    lock.unlock();
    TilePtr t;
    std::string error;
    try {
      t = load(k);
    } catch (const std::exception& e) {
      error = e.what();
    }
    lock.lock();
    loading_.erase(k);
    if (t) {
      insert_locked(k, std::move(t));
      ++stats_.prefetched;
    } else {
      last_error_ = error;
      ++stats_.read_errors;
    }
    changed_.notify_all();
  }
}

template <class T>
void TileCache<T>::wait_idle() const {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return queue_.empty() && loading_.empty(); });
}

template <class T>
bool TileCache<T>::resident(int tx, int ty) const {
  std::lock_guard lock(mutex_);
  return tiles_.count(key(tx, ty)) > 0;
}

template <class T>
bool TileCache<T>::resident_rect(int x, int y, int w, int h) const {
  const int x0 = std::max(x, 0), y0 = std::max(y, 0);
  const int x1 = std::min(x + w, width_) - 1, y1 = std::min(y + h, height_) - 1;
  std::lock_guard lock(mutex_);
  for (int ty = y0 / tile_; ty <= y1 / tile_ && x1 >= x0; ++ty)
    for (int tx = x0 / tile_; tx <= x1 / tile_; ++tx)
      if (!tiles_.count(key(tx, ty))) return false;
  return true;
}

template <class T>
typename TileCache<T>::Stats TileCache<T>::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

template <class T>
std::string TileCache<T>::last_error() const {
  std::lock_guard lock(mutex_);
  return last_error_;
}

template class TileCache<float>;
template class TileCache<Rgb8>;

}  // namespace ig::terrain
